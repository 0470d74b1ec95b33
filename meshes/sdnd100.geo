// SDND100 (docs/verification/sdnd100.md): the node P of the oscillator at the origin and one
// two-node beam from the ground G = (0, 0, -1), across the plane of the motion (x-y), whose bending
// stiffness with the rotations held (12 E I / L^3 in x and in y) and lumped mass stand for the
// deck's isotropic discrete spring and point mass (see input/sdnd100.xml).
// gmsh -1 -format msh41 sdnd100.geo -o sdnd100.msh
Point(1) = {0, 0, -1, 1};
Point(2) = {0, 0, 0, 1};
Line(1) = {1, 2};
Transfinite Curve{1} = 2;
Physical Curve("SPRING") = {1};
Physical Point("G") = {1};
Physical Point("P") = {2};
