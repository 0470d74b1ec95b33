// Two square steel plates stacked, not joined (input/stacked_plates.xml): the lower plate
// a x a x t of (n + 1) x (n + 1) x 2 HEX8 on z in [0, t], the upper one a x a x t of n x n x 2
// on z in [t, 2 t]; the faces at z = t are non-matching, so every upper node lies inside a lower
// face. Groups: LOWER, UPPER (volumes), BASE (z = 0), LOWER_TOP, UPPER_BOTTOM (the contact
// faces), UPPER_TOP.
//   gmsh -3 -setnumber n 30 stacked_plates.geo -o stacked_plates.msh -format msh41
Geometry.AutoCoherence = 0;  // the plates' coincident corners stay two bodies' points
If (!Exists(n)) n = 30; EndIf
a = 0.1; t = 0.01;
For k In {0:1}
  z = k * t;
  p1 = 1000 * k + 1;
  Point(p1) = {0, 0, z}; Point(p1 + 1) = {a, 0, z}; Point(p1 + 2) = {a, a, z}; Point(p1 + 3) = {0, a, z};
  Line(p1) = {p1, p1 + 1}; Line(p1 + 1) = {p1 + 1, p1 + 2}; Line(p1 + 2) = {p1 + 2, p1 + 3}; Line(p1 + 3) = {p1 + 3, p1};
  Curve Loop(p1) = {p1, p1 + 1, p1 + 2, p1 + 3};
  Plane Surface(p1) = {p1};
  Transfinite Curve{p1, p1 + 1, p1 + 2, p1 + 3} = n + 2 - k;
  Transfinite Surface{p1}; Recombine Surface{p1};
  out[] = Extrude {0, 0, t} { Surface{p1}; Layers{2}; Recombine; };
  If (k == 0)
    Physical Volume("LOWER") = {out[1]}; Physical Surface("LOWER_TOP") = {out[0]}; Physical Surface("BASE") = {p1};
  Else
    Physical Volume("UPPER") = {out[1]}; Physical Surface("UPPER_BOTTOM") = {p1}; Physical Surface("UPPER_TOP") = {out[0]};
  EndIf
EndFor
