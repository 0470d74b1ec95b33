// The lower half of meshes/hertz_axisymmetric.geo's sphere (R = 10 mm, axisymmetric: x = r,
// y the axis), for input/hertz_static.xml: pressed slowly by a rigid plane rising from its
// lowest point O = (0, 0) while its equator plane y = R (EQUATOR) slides without lifting. The
// same mesh sizes: TRI6 of h (default 0.05 mm) near O, H (1 mm) beyond 3 mm from it.
// meshes/make-meshes.sh:
//   gmsh -2 -order 2 -format msh41 meshes/hertz_hemisphere.geo -o meshes/hertz_hemisphere.msh
If (!Exists(h))
  h = 5e-5;
EndIf
If (!Exists(H))
  H = 1e-3;
EndIf
R = 0.01;
Point(1) = {0, 0, 0};       // O
Point(2) = {0, R, 0};       // C, the centre
Point(3) = {R, R, 0};       // E, on the equator
Circle(1) = {1, 2, 3};      // O -> E: the contact surface
Line(2) = {3, 2};           // the equator plane
Line(3) = {2, 1};           // the axis
Curve Loop(1) = {1, 2, 3};
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
Physical Curve("EQUATOR") = {2};
Physical Curve("AXIS") = {3};
Physical Point("O") = {1};
