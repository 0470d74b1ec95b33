// Example 02: a one-degree-of-freedom oscillator made of one two-node beam element (BEAM2)
// from the ground G = (-1, 0, 0) to the moving node P at the origin. With DX the only unknown
// (the input's 'Active Components'), the beam is a spring of stiffness E A / L and its lumped
// mass puts rho A L / 2 on P (the ground node's half is fixed): a mass on a spring.
// Regenerate (from this directory):  gmsh -1 -format msh41 oscillator.geo -o oscillator.msh
Point(1) = {-1, 0, 0, 1};
Point(2) = {0, 0, 0, 1};
Line(1) = {1, 2};
Transfinite Curve{1} = 2;        // one element
Physical Curve("SPRING") = {1};  // the element block
Physical Point("G") = {1};       // the ground (clamped)
Physical Point("P") = {2};       // the mass
