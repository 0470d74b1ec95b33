// Example 03: a steel bar, L = 0.1 m along z with a 0.01 x 0.01 m square section, meshed with
// n HEX8 along (default 40, h = 2.5 mm) and m x m across (default 2 x 2), by extruding a
// transfinite quadrilateral section. Physical groups:
//   BAR      (volume)   the element block; also a node set of every node (initial velocity);
//   BOTTOM   (surface)  the lower face z = 0: a side set (the contact surface) and a node set;
//   TOP      (surface)  the upper face z = L;
//   P_BOTTOM (point)    the corner (0, 0, 0) of the lower face, for the history;
//   P_TOP    (point)    the corner (0, 0, L) above it.
// Regenerate (from this directory):  gmsh -3 -format msh41 bar.geo -o bar.msh
// Finer: gmsh -3 -format msh41 -setnumber n 80 bar.geo -o bar.msh (then halve the time step)
If (!Exists(n))
  n = 40;
EndIf
If (!Exists(m))
  m = 2;
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
