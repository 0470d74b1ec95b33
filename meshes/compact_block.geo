// A compact steel block for the direct solvers' benchmark (tools/bench/bench_block_drop.py): a
// cube of side a = 0.1 m from z = 0 (its lower face 'bottom', which meets the rigid plane z = 0)
// to z = a, n x n x n HEX8 (n = 10 by default: 1,331 nodes, 3,993 unknowns; n = 20: 27,783; n =
// 30: 89,373, the compact block of the phase's issue). 'top' is the upper face, 'corner' the node
// (0, 0, a).
//   gmsh -3 -format msh41 -setnumber n 20 meshes/compact_block.geo -o block_20.msh
If (!Exists(n))
  n = 10;
EndIf
a = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a, a, 0};
Point(4) = {0, a, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1:4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 0, a} { Surface{1}; Layers{n}; Recombine; };
e = 1e-7;
corner[] = Point In BoundingBox{-e, -e, a - e, e, e, a + e};
Physical Volume("block") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
Physical Point("corner") = {corner[]};
