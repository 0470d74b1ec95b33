// Example 05: a steel block, 0.1 x 0.1 x 0.1 m, meshed with n x n x k HEX8 (default 4 x 4 x 2)
// by extruding a transfinite quadrilateral base. It stands on the plane z = 0.
// Physical groups:
//   BLOCK  (volume)   the element block; also a node set of every node (initial velocity);
//   BOTTOM (surface)  the base z = 0: the contact surface (a side set);
//   TOP    (surface)  the top face z = 0.1, loaded by the block's weight (a side set);
//   P      (point)    the top corner (0, 0, 0.1), for the history.
// Regenerate (from this directory):  gmsh -3 -format msh41 block.geo -o block.msh
If (!Exists(n))
  n = 4;
EndIf
If (!Exists(k))
  k = 2;   // at least 2 through the height: see the input's 'Contact Mass'
EndIf
a = 0.1;
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {a, a, 0}; Point(4) = {0, a, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
b[] = Extrude {0, 0, a} { Surface{1}; Layers{k}; Recombine; };
Physical Volume("BLOCK") = {b[1]};
Physical Surface("BOTTOM") = {1};
Physical Surface("TOP") = {b[0]};
Physical Point("P") = {5};
