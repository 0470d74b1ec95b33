// The contact patch test (docs/verification/patch-test.md): two blocks 0.02 x 0.02 x 0.01 m
// stacked at z = 0, 1e-6 m apart. The upper block (UPPER, z in [g, g + 0.01]) is HEX8 with an m x m section (2
// layers); the lower block (LOWER, z in [-0.01, 0]) is TET4 on a k x k grid of squares cut into
// triangles (2 layers, each prism cut into three tetrahedra); with tet = 0 the lower block is
// meshed like the upper one (HEX8, m x m): matching contact faces.
// Side sets: UPPER_BOTTOM, LOWER_TOP (the contact faces), UPPER_TOP (loaded; its edges
// UPPER_TOP_EDGE and corners UPPER_TOP_CORNER for consistent nodal forces), LOWER_BASE (supported).
// meshes/make-meshes.sh (the committed non-matching mesh, m = 3, k = 4):
//   gmsh -3 -format msh41 meshes/patch_test.geo -o meshes/patch_test.msh
If (!Exists(m))
  m = 3;
EndIf
If (!Exists(k))
  k = 4;
EndIf
If (!Exists(tet))
  tet = 1;
EndIf
a = 0.02; H = 0.01;
g = 1e-6;  // initial gap: the two faces do not share points (gmsh would merge their nodes)

// Lower block: its upper face at z = 0, extruded downwards.
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, a, 0}; Point(4) = {0, a, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
If (tet)
  Transfinite Curve{1, 2, 3, 4} = k + 1;
  lo[] = Extrude {0, 0, -H} { Surface{1}; Layers{2}; };
Else
  Transfinite Curve{1, 2, 3, 4} = m + 1;
  Recombine Surface{1};
  lo[] = Extrude {0, 0, -H} { Surface{1}; Layers{2}; Recombine; };
EndIf

// Upper block: its upper face at z = g + H, extruded downwards to z = g.
Point(101) = {0, 0, g + H}; Point(102) = {a, 0, g + H}; Point(103) = {a, a, g + H};
Point(104) = {0, a, g + H};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = m + 1;
Transfinite Surface{101};
Recombine Surface{101};
up[] = Extrude {0, 0, -H} { Surface{101}; Layers{2}; Recombine; };

Physical Volume("LOWER") = {lo[1]};
Physical Volume("UPPER") = {up[1]};
Physical Surface("LOWER_TOP") = {1};
Physical Surface("LOWER_BASE") = {lo[0]};
Physical Surface("UPPER_BOTTOM") = {up[0]};
Physical Surface("UPPER_TOP") = {101};
Physical Curve("UPPER_TOP_EDGE") = {101, 102, 103, 104};
Physical Point("UPPER_TOP_CORNER") = {101, 102, 103, 104};
