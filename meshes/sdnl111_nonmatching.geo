// SDNL111's two bars on non-matching meshes: bar 1 (POU1, master) in HEX8 with a
// 3 x 3 section, bar 2 (POU2, slave) in TET4 on a section of 2 x 2 squares cut into triangles
// (each prism cut into three tetrahedra): no node of bar 2's contact face meets one of bar 1's
// except the corners. Section 0.02 x 0.02, bar 1 from z = 1e-5 to 1.00001, bar 2 from z = -1
// to 0, n layers along each (default 100). Physical names as meshes/sdnl111_3d_bars.geo.
// meshes/make-meshes.sh:
//   gmsh -3 -format msh41 meshes/sdnl111_nonmatching.geo -o meshes/sdnl111_nonmatching.msh
a = 0.02;
L = 1.0;
g = 1e-5;
If (!Exists(n))
  n = 100;
EndIf

Point(1) = {0, 0, g};  Point(2) = {a, 0, g};  Point(3) = {a, a, g};  Point(4) = {0, a, g};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 4;
Transfinite Surface{1};
Recombine Surface{1};
bar1[] = Extrude {0, 0, L} { Surface{1}; Layers{n}; Recombine; };

Point(101) = {0, 0, -L}; Point(102) = {a, 0, -L}; Point(103) = {a, a, -L}; Point(104) = {0, a, -L};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 3;
Transfinite Surface{101};
bar2[] = Extrude {0, 0, L} { Surface{101}; Layers{n}; };

Physical Volume("POU1") = {bar1[1]};
Physical Volume("POU2") = {bar2[1]};
Physical Surface("CNT_POU1") = {1};
Physical Surface("CNT_POU2") = {bar2[0]};
Physical Surface("CL_POU2") = {101};
Physical Point("N1") = {1};
Physical Point("A") = {1};
