// A slender beam L = 1 m along x with a square section h = b = 20 mm (y in [-h/2, h/2], z in
// [0, b]), for the large-deflection cantilever (input/elastica_beam.xml, tests/cli/
// scripts/elastica.py, docs/verification/elastica.md). The section is two layers (y < 0 and
// y > 0), so the centre line y = 0, z = 0 is a line of nodes whose end is the node set "TIP".
// nx elements along, one per layer through the thickness, one across; HEX20 when hex = 1
// (-order 2 with Mesh.SecondOrderIncomplete = 1), else TET10 (each prism split in three):
//   gmsh -3 -order 2 -setnumber nx 16 -setnumber hex 1 -format msh41 elastica_beam.geo -o beam.msh
// Groups: volume "BEAM", surfaces "CLAMPED" (x = 0) and "END" (x = L), point "TIP" (L, 0, 0).
If (!Exists(nx))
  nx = 16;
EndIf
If (!Exists(hex))
  hex = 1;
EndIf
Mesh.SecondOrderIncomplete = 1;
L = 1.0;
h = 0.02;
b = 0.02;
Point(1) = {0, -h / 2, 0}; Point(2) = {0, 0, 0}; Point(3) = {0, h / 2, 0};
Point(4) = {0, h / 2, b}; Point(5) = {0, 0, b}; Point(6) = {0, -h / 2, b};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Transfinite Curve{1:7} = 2;
Transfinite Surface{1, 2};
If (hex)
  Recombine Surface{1, 2};
  out[] = Extrude {L, 0, 0} { Surface{1, 2}; Layers{nx}; Recombine; };
Else
  out[] = Extrude {L, 0, 0} { Surface{1, 2}; Layers{nx}; };
EndIf
Physical Volume("BEAM") = Volume{:};
Physical Surface("CLAMPED") = {1, 2};
e = 1e-6;
Physical Surface("END") = Surface In BoundingBox{L - e, -h, -e, L + e, h, b + e};
Physical Point("TIP") = Point In BoundingBox{L - e, -e, -e, L + e, e, e};
