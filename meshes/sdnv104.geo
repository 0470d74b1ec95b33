// SDNV104 (docs/verification/sdnv104.md): a 1 m x 1 m pad (plane strain, unit thickness) on a
// frame 18 m long, along which it slides up to 15 m. The pad (PAD, 4 x 4 elements of 0.25 m)
// sits with its lower edge PAD_BOTTOM (the slave) on the frame's upper edge FRAME_TOP (the
// master, 36 edges of 0.5 m: the meshes do not match) at y = 0, from x = 0 to 1; the frame
// (FRAME, 0.5 m deep, from x = -1 to 17) is clamped along FRAME_BASE. The pressures act on
// PAD_TOP (downwards) and PAD_LEFT (along +x); PAD_SPRING holds the mid-height nodes of the
// pad's two lateral edges, where the springs to the fixed points are tied.
// quad = 1 (default) gives QUAD4 (gmsh -2), with -order 2 QUAD8. meshes/make-meshes.sh:
//   gmsh -2 -format msh41 meshes/sdnv104.geo -o meshes/sdnv104_quad4.msh
//   gmsh -2 -order 2 -format msh41 meshes/sdnv104.geo -o meshes/sdnv104_quad8.msh
Mesh.SecondOrderIncomplete = 1;  // QUAD8, not QUAD9
If (!Exists(n))
  n = 4;  // pad elements along each side
EndIf
If (!Exists(nf))
  nf = 36;  // frame edges along x
EndIf

// Pad, counter-clockwise (outward edge normals); its lateral edges split at mid-height.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 0.5, 0}; Point(4) = {1, 1, 0};
Point(5) = {0, 1, 0}; Point(6) = {0, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Transfinite Curve{1, 4} = n + 1;
Transfinite Curve{2, 3, 5, 6} = n / 2 + 1;
Transfinite Surface{1} = {1, 2, 4, 5};
Recombine Surface{1};

// Frame.
Point(11) = {-1, -0.5, 0}; Point(12) = {17, -0.5, 0}; Point(13) = {17, 0, 0}; Point(14) = {-1, 0, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Transfinite Curve{11, 13} = nf + 1;
Transfinite Curve{12, 14} = 2;
Transfinite Surface{11};
Recombine Surface{11};

// The frame-invariance check (tests/cli/scripts/sdnv104.py) turns the whole scene by 'angle'
// radians about z through the origin (gmsh -setnumber angle A).
If (!Exists(angle))
  angle = 0;
EndIf
If (angle != 0)
  Rotate {{0, 0, 1}, {0, 0, 0}, angle} { Surface{1, 11}; }
EndIf

Physical Surface("PAD") = {1};
Physical Surface("FRAME") = {11};
Physical Curve("PAD_BOTTOM") = {1};
Physical Curve("PAD_TOP") = {4};
Physical Curve("PAD_LEFT") = {5, 6};
Physical Curve("FRAME_TOP") = {13};
Physical Curve("FRAME_BASE") = {11};
Physical Point("PAD_SPRING") = {3, 6};
