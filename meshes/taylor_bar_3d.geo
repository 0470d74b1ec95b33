// The Taylor bar in 3D (docs/verification/taylor-bar.md): the copper cylinder of radius R = 3.2 mm
// and length L = 32.4 mm along y, its impact face y = 0, meshed with hexahedra by an O-grid of
// the section (a square core of n x n elements and a ring of n / 2 radial layers around it:
// about n elements across the radius, 2n along a quarter of the rim) extruded in round(n L / R)
// layers. full = 0 (default): the quarter x >= 0, z >= 0 with its symmetry planes as side sets
// SYMX (x = 0) and SYMZ (z = 0); full = 1: the whole bar. Node sets: EDGE (R, 0, 0), the impact
// face's edge on the x axis; CENTRE (0, 0, 0); REAR (0, L, 0). tets = 1: the same grid in
// tetrahedra (each hexahedron's place cut into two prisms, each prism into three tetrahedra; with
// -order 2, TET10).
//   gmsh -3 -format msh41 -setnumber n 4 meshes/taylor_bar_3d.geo -o bar.msh
If (!Exists(n))
  n = 4;
EndIf
If (!Exists(tets))
  tets = 0;
EndIf
If (!Exists(full))
  full = 0;
EndIf
R = 0.0032;
L = 0.0324;
a = 0.5 * R;   // the core square's half side
k = n / 2;     // the ring's radial layers
m = Round(n * L / R);
c = R / Sqrt(2);
Point(1) = {0, 0, 0};
// The quarter x >= 0, z >= 0, turned by q right angles about y for the full bar; each quarter
// takes over the curves it shares with the one before (and the last with the first).
quarters = full ? 4 : 1;
core[] = {};
For q In {0 : quarters - 1}
  cs = Cos(q * Pi / 2); sn = Sin(q * Pi / 2);
  // (x, z) turned by q quarters: x' = x cs - z sn, z' = x sn + z cs
  If (q == 0)
    p2 = newp; Point(p2) = {a, 0, 0};
    p3 = newp; Point(p3) = {R, 0, 0};
    l1 = newl; Line(l1) = {1, p2};
    l5 = newl; Line(l5) = {p2, p3};
    first2 = p2; first3 = p3; firstl1 = l1; firstl5 = l5;
  Else
    p2 = last6; p3 = last7; l1 = -lastl4; l5 = -lastl9;
  EndIf
  p4 = newp; Point(p4) = {c * cs - c * sn, 0, c * sn + c * cs};
  p5 = newp; Point(p5) = {a * cs - a * sn, 0, a * sn + a * cs};
  If (full && q == 3)
    p6 = first2; p7 = first3;
  Else
    p6 = newp; Point(p6) = {-a * sn, 0, a * cs};
    p7 = newp; Point(p7) = {-R * sn, 0, R * cs};
  EndIf
  l2 = newl; Line(l2) = {p2, p5};
  l3 = newl; Line(l3) = {p5, p6};
  l6 = newl; Circle(l6) = {p3, 1, p4};
  l7 = newl; Line(l7) = {p4, p5};
  l8 = newl; Circle(l8) = {p4, 1, p7};
  If (full && q == 3)
    l4 = -firstl1; l9 = -firstl5;
  Else
    l4 = newl; Line(l4) = {p6, 1};
    l9 = newl; Line(l9) = {p7, p6};
  EndIf
  Transfinite Curve{Abs(l1), l2, l3, Abs(l4), l6, l8} = n + 1;
  Transfinite Curve{Abs(l5), l7, Abs(l9)} = k + 1;
  s1 = news; Curve Loop(s1) = {l1, l2, l3, l4}; Plane Surface(s1) = {s1};
  s2 = news; Curve Loop(s2) = {l5, l6, l7, -l2}; Plane Surface(s2) = {s2};
  s3 = news; Curve Loop(s3) = {-l7, l8, l9, -l3}; Plane Surface(s3) = {s3};
  Transfinite Surface{s1, s2, s3};
  If (!tets)
    Recombine Surface{s1, s2, s3};
  EndIf
  core[] += {s1, s2, s3};
  last6 = p6; last7 = p7; lastl4 = l4; lastl9 = l9;
EndFor
If (tets)
  out[] = Extrude {0, L, 0} { Surface{core[]}; Layers{m}; };
Else
  out[] = Extrude {0, L, 0} { Surface{core[]}; Layers{m}; Recombine; };
EndIf
e = 1e-7;
Physical Volume("BAR") = Volume{:};
Physical Surface("IMPACT") = Surface In BoundingBox{-R - e, -e, -R - e, R + e, e, R + e};
If (!full)
  Physical Surface("SYMX") = Surface In BoundingBox{-e, -e, -e, e, L + e, R + e};
  Physical Surface("SYMZ") = Surface In BoundingBox{-e, -e, -e, R + e, L + e, e};
EndIf
Physical Point("EDGE") = Point In BoundingBox{R - e, -e, -e, R + e, e, e};
Physical Point("CENTRE") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("REAR") = Point In BoundingBox{-e, L - e, -e, e, L + e, e};
