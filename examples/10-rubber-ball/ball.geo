// Hertz impact (docs/verification/hertz.md): a steel sphere of radius R = 10 mm as an axisymmetric
// half disc in the x-y plane (x = r >= 0, y the axis), centre C = (0, R), lowest point
// O = (0, 0) touching the rigid plane y = 0 (given in the input as an obstacle). Quadratic
// triangles (TRI6 with -order 2), of size h near O (default 0.05 mm, about 16 across the
// 0.81 mm contact radius) growing to H (default 1 mm) beyond 3 mm from O.
// meshes/make-meshes.sh:
//   gmsh -2 -order 2 -format msh41 meshes/hertz_axisymmetric.geo -o meshes/hertz_axisymmetric.msh
If (!Exists(h))
  h = 5e-5;
EndIf
If (!Exists(H))
  H = 1e-3;
EndIf
R = 0.01;
Point(1) = {0, 0, 0};       // O, the first point to touch
Point(2) = {0, R, 0};       // C, the centre
Point(3) = {R, R, 0};       // E, on the equator
Point(4) = {0, 2 * R, 0};   // T, the top
Circle(1) = {1, 2, 3};      // O -> E: the lower quarter, the contact surface
Circle(2) = {3, 2, 4};      // E -> T
Line(3) = {4, 2};           // T -> C, on the axis
Line(4) = {2, 1};           // C -> O, on the axis
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 1e-3;
Field[2].DistMax = 3e-3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface("SPHERE") = {1};
Physical Curve("CONTACT") = {1};
Physical Curve("AXIS") = {3, 4};
Physical Point("O") = {1};
Physical Point("C") = {2};
