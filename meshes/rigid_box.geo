// A box of sides a x b x c = 0.1 x 0.2 x 0.4 m (2 x 4 x 8 HEX8) with three distinct principal
// moments (input/rigid_spin.xml: a rigid body spinning near its intermediate axis, BENCHMARKS
// section 17). 'box' is its element block and the node set of all its nodes; 'corner' the node
// (0, 0, 0), 'xedge', 'yedge' and 'zedge' the nodes (a, 0, 0), (0, b, 0) and (0, 0, c).
//   gmsh -3 -format msh41 meshes/rigid_box.geo -o rigid_box.msh
a = 0.1;
b = 0.2;
c = 0.4;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a, b, 0};
Point(4) = {0, b, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3;
Transfinite Curve{2, 4} = 5;
Transfinite Surface{1};
Recombine Surface{1};
box[] = Extrude {0, 0, c} { Surface{1}; Layers{8}; Recombine; };
e = 1e-7;
xedge[] = Point In BoundingBox{a - e, -e, -e, a + e, e, e};
yedge[] = Point In BoundingBox{-e, b - e, -e, e, b + e, e};
zedge[] = Point In BoundingBox{-e, -e, c - e, e, e, c + e};
Physical Volume("box") = {box[1]};
Physical Point("corner") = {1};
Physical Point("xedge") = {xedge[]};
Physical Point("yedge") = {yedge[]};
Physical Point("zedge") = {zedge[]};
