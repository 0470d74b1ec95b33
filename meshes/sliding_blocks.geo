// The sliding scene (input/sliding.xml, input/sliding_friction.xml): a steel block
// (0.04 x 0.016 x 0.02 m, 6 x 3 x 3 HEX8) standing on a longer foundation (0.2 x 0.02 x 0.01 m, 40 x 2 x 2 HEX8: 5 mm faces along x), the two
// meshes not matching (block elements 6.7 x 5.3 mm on its contact face). The block's lower face
// (BLOCK_BOTTOM, the slave) touches the foundation's upper face (FOUNDATION_TOP, the master) at
// z = 0, from x = 0.02 to 0.06 m; the foundation's lower face (FOUNDATION_BASE) is clamped.
// BLOCK_TOP, its four edges (BLOCK_TOP_EDGE) and corners (BLOCK_TOP_CORNER) are node sets for
// the consistent nodal loads of a uniform pressure. meshes/make-meshes.sh:
//   gmsh -3 -format msh41 meshes/sliding_blocks.geo -o meshes/sliding_blocks.msh
If (!Exists(n))
  n = 40;  // foundation elements along x
EndIf
L = 0.2; W = 0.02; H = 0.01;          // foundation
x0 = 0.02; b = 0.04; w = 0.016; h = 0.02;  // block: from x0 along x, centred across
y0 = (W - w) / 2;

// Foundation: its upper face at z = 0, extruded downwards.
Point(1) = {0, 0, 0}; Point(2) = {L, 0, 0}; Point(3) = {L, W, 0}; Point(4) = {0, W, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
// The frame-invariance test (tools/oracles/frame_invariance.py --scene sliding) turns the whole scene by
// 'angle' radians about the axis (ax, ay, az) through the origin: both upper faces are turned,
// then extruded along (dx, dy, dz), the turned (0, 0, -1) that the test passes.
If (!Exists(angle))
  angle = 0; ax = 0; ay = 0; az = 1; dx = 0; dy = 0; dz = -1;
EndIf
If (angle != 0)
  Rotate {{ax, ay, az}, {0, 0, 0}, angle} { Surface{1}; }
EndIf
f[] = Extrude {H * dx, H * dy, H * dz} { Surface{1}; Layers{2}; Recombine; };

// Block: its upper face at z = h, extruded downwards to z = 0.
Point(101) = {x0, y0, h}; Point(102) = {x0 + b, y0, h}; Point(103) = {x0 + b, y0 + w, h};
Point(104) = {x0, y0 + w, h};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104};
Plane Surface(101) = {101};
Transfinite Curve{101, 103} = 7;
Transfinite Curve{102, 104} = 4;
Transfinite Surface{101};
Recombine Surface{101};
If (angle != 0)
  Rotate {{ax, ay, az}, {0, 0, 0}, angle} { Surface{101}; }
EndIf
k[] = Extrude {h * dx, h * dy, h * dz} { Surface{101}; Layers{3}; Recombine; };

Physical Volume("FOUNDATION") = {f[1]};
Physical Volume("BLOCK") = {k[1]};
Physical Surface("FOUNDATION_TOP") = {1};
Physical Surface("FOUNDATION_BASE") = {f[0]};
Physical Surface("BLOCK_BOTTOM") = {k[0]};
Physical Surface("BLOCK_TOP") = {101};
Physical Curve("BLOCK_TOP_EDGE") = {101, 102, 103, 104};
Physical Point("BLOCK_TOP_CORNER") = {101, 102, 103, 104};
