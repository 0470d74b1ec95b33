// Example 04: a steel bar, L = 0.1 m along z with a 0.01 x 0.01 m square section, meshed with
// n HEX8 along (default 100, h = 1 mm) and m x m across (default 1 x 1), by extruding a
// transfinite quadrilateral section. Physical groups:
//   BAR      (volume)   the element block; also a node set of every node;
//   BOTTOM   (surface)  the lower face z = 0 (free), a side set and a node set;
//   TOP      (surface)  the upper face z = L, where the pressure acts (a side set);
//   P_BOTTOM (point)    the corner (0, 0, 0) of the lower face, for the history;
//   P_TOP    (point)    the corner (0, 0, L) above it.
// Regenerate (from this directory):  gmsh -3 -format msh41 bar.geo -o bar.msh
// Coarser: gmsh -3 -format msh41 -setnumber n 25 bar.geo -o bar.msh
If (!Exists(n))
  n = 100;
EndIf
If (!Exists(m))
  m = 1;
EndIf
a = 0.01;
L = 0.1;
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, a, 0}; Point(4) = {0, a, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = m + 1;
Transfinite Surface{1};
Recombine Surface{1};                                        // quadrilaterals, not triangles
bar[] = Extrude {0, 0, L} { Surface{1}; Layers{n}; Recombine; };  // hexahedra
Physical Volume("BAR") = {bar[1]};
Physical Surface("BOTTOM") = {1};
Physical Surface("TOP") = {bar[0]};
Physical Point("P_BOTTOM") = {1};
Physical Point("P_TOP") = {5};
