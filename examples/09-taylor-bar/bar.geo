// The Taylor bar (docs/verification/taylor-bar.md): a copper cylinder of radius R = 3.2 mm and
// length L = 32.4 mm, as the axisymmetric rectangle 0 <= x = r <= R, 0 <= y = z <= L of the
// meridian plane (y the axis), its impact face y = 0. Quadrilaterals, n across the radius
// (default 8) and the same size along the length (round(n L / R) = 81 for n = 8); quadratic
// (QUAD8) with -order 2 and Mesh.SecondOrderIncomplete. tris = 1: each square cut into two
// triangles along alternating diagonals (TRI3; TRI6 with -order 2).
//   gmsh -2 -format msh41 -setnumber n 16 meshes/taylor_bar_axisymmetric.geo -o bar.msh
If (!Exists(n))
  n = 8;
EndIf
If (!Exists(tris))
  tris = 0;
EndIf
R = 0.0032;
L = 0.0324;
m = Round(n * L / R);
Point(1) = {0, 0, 0};     // the impact face's centre: the final length is REAR - CENTRE
Point(2) = {R, 0, 0};     // the impact face's edge: its radius is the test's result
Point(3) = {R, L, 0};
Point(4) = {0, L, 0};     // the rear face's centre: the final length
Line(1) = {1, 2};         // the impact face
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};         // on the axis
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = m + 1;
If (tris)
  Transfinite Surface{1} Alternate;
Else
  Transfinite Surface{1};
  Recombine Surface{1};
EndIf
Mesh.SecondOrderIncomplete = 1;
Physical Surface("BAR") = {1};
Physical Curve("IMPACT") = {1};
Physical Curve("AXIS") = {4};
Physical Point("EDGE") = {2};
Physical Point("REAR") = {4};
Physical Point("CENTRE") = {1};
