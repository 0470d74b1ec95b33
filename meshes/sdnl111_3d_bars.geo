// SDNL111's two 3D bars meshed by gmsh: section 0.02 x 0.02, bar 1 (POU1, A..B) from
// z = 1e-5 to 1.00001, bar 2 (POU2, C..D) from z = -1 to 0, the gap J0 = 1e-5 between C and A.
// Each bar: the square section extruded in n layers (default 50); with hex = 0 (the default)
// the section is two triangles and each prism is cut into three tetrahedra (6 n tetrahedra per
// bar), with hex = 1 it is one quadrangle and each layer one hexahedron. -order 1 gives TET4 or
// HEX8, -order 2 TET10 or HEX20 (Mesh.SecondOrderIncomplete). The physical names are those of
// the HEX8 mesh meshes/sdnl111_3d.exo, so that input/sdnl111c_tet10.xml reads like
// input/sdnl111c.xml. meshes/make-meshes.sh generates the committed TET10 mesh:
//   gmsh -3 -order 2 -format msh41 meshes/sdnl111_3d_bars.geo -o meshes/sdnl111_3d_tet10.msh
// tools/study/bar_convergence.py meshes the other element types and refinements, for example
//   gmsh -3 -order 2 -setnumber n 100 -setnumber hex 1 -format msh41 sdnl111_3d_bars.geo -o b.msh
a = 0.02;      // section side [m]
L = 1.0;       // bar length [m]
g = 1e-5;      // gap J0 [m]
If (!Exists(n))
  n = 50;      // layers along each bar
EndIf
If (!Exists(hex))
  hex = 0;
EndIf
Mesh.SecondOrderIncomplete = 1;

// Bar 1: section at z = g (its contact face), extruded to z = g + L.
Point(1) = {0, 0, g};  Point(2) = {a, 0, g};  Point(3) = {a, a, g};  Point(4) = {0, a, g};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
If (hex)
  Recombine Surface{1};
  bar1[] = Extrude {0, 0, L} { Surface{1}; Layers{n}; Recombine; };
Else
  bar1[] = Extrude {0, 0, L} { Surface{1}; Layers{n}; };
EndIf

// Bar 2: section at z = -L (its clamped face), extruded to z = 0 (its contact face).
// (Tags from 101: the first extrusion numbered its new entities after bar 1's.)
Point(101) = {0, 0, -L}; Point(102) = {a, 0, -L}; Point(103) = {a, a, -L}; Point(104) = {0, a, -L};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 2;
Transfinite Surface{101};
If (hex)
  Recombine Surface{101};
  bar2[] = Extrude {0, 0, L} { Surface{101}; Layers{n}; Recombine; };
Else
  bar2[] = Extrude {0, 0, L} { Surface{101}; Layers{n}; };
EndIf

Physical Volume("POU1") = {bar1[1]};
Physical Volume("POU2") = {bar2[1]};
Physical Surface("CNT_POU1") = {1};        // bar 1's face at z = g (master)
Physical Surface("CNT_POU2") = {bar2[0]};  // bar 2's face at z = 0 (slave)
Physical Surface("CL_POU2") = {101};       // bar 2's face at z = -L (clamped)
Physical Point("N1") = {1};                // point A
Physical Point("A") = {1};
