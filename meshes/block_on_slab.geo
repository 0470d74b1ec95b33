// A compact steel block dropped flat on a meshed slab (issue 73's friction scene): the cube of
// side a = 0.1 m from z = 0 to z = a (n x n x n HEX8; 'bottom' its lower face, 'corner' the node
// (0, 0, a)) above a slab of side s = 0.2 m centred under it, from z = -t to z = 0 (m x m x k
// HEX8; 'slab_top' its upper face, touching 'bottom' at t = 0 on non-matching nodes, 'slab_base'
// its lower face). n = 20, m = 40, k = 6: 21,028 nodes, 58,041 unknowns once the base is clamped.
//   gmsh -3 -format msh41 -setnumber n 20 -setnumber m 40 meshes/block_on_slab.geo -o block_on_slab.msh
If (!Exists(n))
  n = 20;
EndIf
If (!Exists(m))
  m = 40;
EndIf
If (!Exists(k))
  k = 6;
EndIf
a = 0.1;
s = 0.2;
t = 0.02;
c = (s - a) / 2;
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
block[] = Extrude {0, 0, a} { Surface{1}; Layers{n}; Recombine; };
Point(101) = {-c, -c, -t};
Point(102) = {a + c, -c, -t};
Point(103) = {a + c, a + c, -t};
Point(104) = {-c, a + c, -t};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101:104} = m + 1;
Transfinite Surface{101};
Recombine Surface{101};
slab[] = Extrude {0, 0, t} { Surface{101}; Layers{k}; Recombine; };
e = 1e-7;
corner[] = Point In BoundingBox{-e, -e, a - e, e, e, a + e};
Physical Volume("block") = {block[1]};
Physical Volume("slab") = {slab[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {block[0]};
Physical Surface("slab_top") = {slab[0]};
Physical Surface("slab_base") = {101};
Physical Point("corner") = {corner[]};
