// SDND101 (docs/verification/sdnd101.md) and SDND100-like one-node scenes: the node P of the
// oscillator at the origin and one two-node beam from the ground G = (-1, 0, 0), whose axial stiffness and
// lumped mass stand for the deck's discrete spring and point mass (see input/sdnd101.xml).
// gmsh -1 -format msh41 sdnd101.geo -o sdnd101.msh
Point(1) = {-1, 0, 0, 1};
Point(2) = {0, 0, 0, 1};
Line(1) = {1, 2};
Transfinite Curve{1} = 2;
Physical Curve("SPRING") = {1};
Physical Point("G") = {1};
Physical Point("P") = {2};
