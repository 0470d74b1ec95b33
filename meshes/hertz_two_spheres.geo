// Two steel spheres colliding head on (tests/cli/scripts/two_spheres.py): meshes/
// hertz_axisymmetric.geo's half disc (x = r >= 0, y the axis, centre C = (0, R), lowest point O
// at the origin) and its mirror image below the plane y = -g/2, centre C2 = (0, -R - g), its
// highest point O2 = (0, -g): a gap g = 1 nm, so that gmsh keeps O and O2 apart. Each sphere is
// meshed on its own (the two meshes are not mirror images node for node, but the nodes of the
// two contact arcs nearly face each other). TRI6 of size h near O and O2, H beyond 3 mm.
// meshes/make-meshes.sh:
//   gmsh -2 -order 2 -format msh41 meshes/hertz_two_spheres.geo -o meshes/hertz_two_spheres.msh
If (!Exists(h))
  h = 5e-5;
EndIf
If (!Exists(H))
  H = 1e-3;
EndIf
R = 0.01;
g = 1e-9;
Point(1) = {0, 0, 0};         // O
Point(2) = {0, R, 0};         // C
Point(3) = {R, R, 0};
Point(4) = {0, 2 * R, 0};
Circle(1) = {1, 2, 3};        // the upper sphere's contact arc
Circle(2) = {3, 2, 4};
Line(3) = {4, 2};
Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point(11) = {0, -g, 0};       // O2
Point(12) = {0, -R - g, 0};   // C2
Point(13) = {R, -R - g, 0};
Point(14) = {0, -2 * R - g, 0};
Circle(11) = {11, 12, 13};    // the lower sphere's contact arc
Circle(12) = {13, 12, 14};
Line(13) = {14, 12};
Line(14) = {12, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {-11};
Field[1] = Distance;
Field[1].PointsList = {1, 11};
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
Physical Surface("LOWER") = {11};
Physical Curve("CONTACT") = {1};
Physical Curve("LOWER_CONTACT") = {11};
Physical Curve("AXIS") = {3, 4, 13, 14};
Physical Point("O") = {1};
Physical Point("C") = {2};
Physical Point("C2") = {12};
