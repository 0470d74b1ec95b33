// A cantilever block 1 x 0.2 x 0.2 m (the modal convergence study, tools/study/modal_convergence.py,
// docs/verification/modal-convergence.md),
// clamped on its face x = 0 (physical surface "clamped"), meshed with n elements across and
// 5 n along: hexahedra when hex = 1 (HEX20 with -order 2 and Mesh.SecondOrderIncomplete = 1),
// else tetrahedra (TET10 with -order 2). For example:
//   gmsh -3 -order 2 -setnumber n 4 -setnumber hex 1 -format msh41 cantilever_block.geo -o c.msh
If (!Exists(n))
  n = 2;
EndIf
If (!Exists(hex))
  hex = 1;
EndIf
Mesh.SecondOrderIncomplete = 1;
a = 0.2;
L = 1.0;
Point(1) = {0, 0, 0}; Point(2) = {0, a, 0}; Point(3) = {0, a, a}; Point(4) = {0, 0, a};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
If (hex)
  Recombine Surface{1};
  out[] = Extrude {L, 0, 0} { Surface{1}; Layers{5 * n}; Recombine; };
Else
  out[] = Extrude {L, 0, 0} { Surface{1}; Layers{5 * n}; };
EndIf
Physical Volume("block") = {out[1]};
Physical Surface("clamped") = {1};
