// SDNV100 (docs/verification/sdnv100.md): a steel bar 0.2 m long with a 0.02 x 0.02 m square section
// along z, from z = 0 (its lower face FACEINF, which meets the rigid wall) to z = 0.2 (its
// upper face FACESUP), meshed with n HEX8 along and one across (default n = 20, 10 mm: about
// the deck's own mesh, 21 HEXA8 along). N5 is a corner of the lower face, N100 the corner
// above it on the upper face. The wall is not meshed: the inputs give it as a rigid plane
// obstacle 2 mm below. meshes/make-meshes.sh:
//   gmsh -3 -format msh41 meshes/sdnv100_bar.geo -o meshes/sdnv100_bar.msh
If (!Exists(n))
  n = 20;
EndIf
// m HEX8 across each side of the section (default 1).
If (!Exists(m))
  m = 1;
EndIf
a = 0.02;
L = 0.2;
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, a, 0}; Point(4) = {0, a, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = m + 1;
Transfinite Surface{1};
Recombine Surface{1};
// The frame-invariance test (tools/oracles/frame_invariance.py) turns the bar by 'angle' radians
// about the axis (ax, ay, az) through the origin: the section is turned, then extruded along
// (dx, dy, dz), the turned (0, 0, L) that the test passes.
If (Exists(angle))
  Rotate {{ax, ay, az}, {0, 0, 0}, angle} { Surface{1}; }
Else
  dx = 0; dy = 0; dz = L;
EndIf
bar[] = Extrude {dx, dy, dz} { Surface{1}; Layers{n}; Recombine; };
Physical Volume("BAR") = {bar[1]};
Physical Surface("FACEINF") = {1};
Physical Surface("FACESUP") = {bar[0]};
Physical Point("N5") = {1};
Physical Point("N100") = {5};
