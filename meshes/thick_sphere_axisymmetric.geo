// A thick-walled hollow sphere for the inflation test (docs/verification/thick-sphere.md): inner
// radius A = 50 mm, outer B = 100 mm, as an axisymmetric quarter annulus in the x-y plane (x = r
// >= 0, y the axis), the equator y = 0 a symmetry plane. Quadratic quadrilaterals (QUAD8 with
// -order 2 and Mesh.SecondOrderIncomplete), n across the wall (default 4) and 2 n along the
// quarter.
//   gmsh -2 -order 2 -format msh41 -setnumber n 8 meshes/thick_sphere_axisymmetric.geo -o s.msh
If (!Exists(n))
  n = 4;
EndIf
A = 0.05;
B = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {A, 0, 0};       // inner equator
Point(3) = {B, 0, 0};       // outer equator
Point(4) = {0, B, 0};       // outer pole
Point(5) = {0, A, 0};       // inner pole
Line(1) = {2, 3};           // the equator plane
Circle(2) = {3, 1, 4};      // outer surface
Line(3) = {4, 5};           // on the axis
Circle(4) = {5, 1, 2};      // inner surface
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 2 * n + 1;
Transfinite Surface{1};
Recombine Surface{1};
Mesh.SecondOrderIncomplete = 1;
Physical Surface("SPHERE") = {1};
Physical Curve("INNER") = {4};
Physical Curve("EQUATOR") = {1};
Physical Curve("AXIS") = {3};
Physical Point("INNER_EQUATOR") = {2};
Physical Point("INNER_POLE") = {5};
Physical Point("OUTER_EQUATOR") = {3};
