// The copper bar probe (energy of penalty contact with every scheme): a cylinder of
// radius R = 3.2 mm and length L = 32.4 mm along z, from z = 0 (its lower face 'impact', which
// hits the rigid plane z = 0) to z = L (its upper face 'far'), in HEX8. The disk is an O-grid of
// quadrilaterals: a square core of half-side s = 0.45 R (four quadrants of nc x nc QUAD4 around
// the centre) and eight curved blocks of nc x m QUAD4 between the square and the circle (each
// from a corner of the square to an axis point of it, 8 nc segments on the circle), extruded
// along z in nz layers. Default nc = 2, m = 2, nz = 24: 57 nodes per section, 1,425 nodes,
// 4,275 unknowns, 1,152 HEX8; elements 0.72 mm in the core, 0.6 to 0.9 mm radially, 1.26 mm
// along the circle, 1.35 mm along z. 'centre' is the centre of the impact face, 'top' the
// centre of the far face. The circle is a 16-gon of straight faces: the mesh's section is
// (4 nc / pi) sin(pi / (4 nc)) = 97.45 % of pi R^2 at nc = 2 (its mass 9.070 g, not 9.308 g).
// meshes/make-meshes.sh:
//   gmsh -3 -format msh41 meshes/copper_bar.geo -o meshes/copper_bar.msh
If (!Exists(nc))
  nc = 2;
EndIf
If (!Exists(m))
  m = 2;
EndIf
If (!Exists(nz))
  nz = 24;
EndIf
R = 3.2e-3;
L = 32.4e-3;
s = 0.45 * R;
c = R / Sqrt(2);

Point(1) = {0, 0, 0};
// The square core: its axis points (2..5) and corners (6..9).
Point(2) = {s, 0, 0}; Point(3) = {0, s, 0}; Point(4) = {-s, 0, 0}; Point(5) = {0, -s, 0};
Point(6) = {s, s, 0}; Point(7) = {-s, s, 0}; Point(8) = {-s, -s, 0}; Point(9) = {s, -s, 0};
// The circle: its axis points (12..15) and diagonal points (16..19).
Point(12) = {R, 0, 0}; Point(13) = {0, R, 0}; Point(14) = {-R, 0, 0}; Point(15) = {0, -R, 0};
Point(16) = {c, c, 0}; Point(17) = {-c, c, 0}; Point(18) = {-c, -c, 0}; Point(19) = {c, -c, 0};

// Core: spokes from the centre (1..4) and the square's half sides (5..12).
Line(1) = {1, 2}; Line(2) = {1, 3}; Line(3) = {1, 4}; Line(4) = {1, 5};
Line(5) = {2, 6}; Line(6) = {6, 3}; Line(7) = {3, 7}; Line(8) = {7, 4};
Line(9) = {4, 8}; Line(10) = {8, 5}; Line(11) = {5, 9}; Line(12) = {9, 2};
// Radial lines from the square to the circle (13..20).
Line(13) = {2, 12}; Line(14) = {6, 16}; Line(15) = {3, 13}; Line(16) = {7, 17};
Line(17) = {4, 14}; Line(18) = {8, 18}; Line(19) = {5, 15}; Line(20) = {9, 19};
// The circle in eight arcs (21..28), centre point 1.
Circle(21) = {12, 1, 16}; Circle(22) = {16, 1, 13}; Circle(23) = {13, 1, 17};
Circle(24) = {17, 1, 14}; Circle(25) = {14, 1, 18}; Circle(26) = {18, 1, 15};
Circle(27) = {15, 1, 19}; Circle(28) = {19, 1, 12};

// The four core quadrants (1..4).
Curve Loop(1) = {1, 5, 6, -2};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 7, 8, -3};   Plane Surface(2) = {2};
Curve Loop(3) = {3, 9, 10, -4};  Plane Surface(3) = {3};
Curve Loop(4) = {4, 11, 12, -1}; Plane Surface(4) = {4};
// The eight ring blocks (5..12).
Curve Loop(5) = {5, 14, -21, -13};  Plane Surface(5) = {5};
Curve Loop(6) = {6, 15, -22, -14};  Plane Surface(6) = {6};
Curve Loop(7) = {7, 16, -23, -15};  Plane Surface(7) = {7};
Curve Loop(8) = {8, 17, -24, -16};  Plane Surface(8) = {8};
Curve Loop(9) = {9, 18, -25, -17};  Plane Surface(9) = {9};
Curve Loop(10) = {10, 19, -26, -18}; Plane Surface(10) = {10};
Curve Loop(11) = {11, 20, -27, -19}; Plane Surface(11) = {11};
Curve Loop(12) = {12, 13, -28, -20}; Plane Surface(12) = {12};

Transfinite Curve{1:12, 21:28} = nc + 1;
Transfinite Curve{13:20} = m + 1;
Transfinite Surface{1:12};
Recombine Surface{1:12};

out[] = Extrude {0, 0, L} { Surface{1:12}; Layers{nz}; Recombine; };
// Extrude returns, per surface: its top, its volume, its four lateral surfaces.
far[] = {};
For i In {0:11}
  far[] += out[6 * i];
EndFor

e = 1e-7;
top[] = Point In BoundingBox{-e, -e, L - e, e, e, L + e};
Physical Volume("bar") = Volume{:};
Physical Surface("impact") = {1:12};
Physical Surface("far") = {far[]};
Physical Point("centre") = {1};
Physical Point("top") = {top[]};
