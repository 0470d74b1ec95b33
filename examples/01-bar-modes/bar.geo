// Example 01: a straight steel bar of length L = 1 m along x, meshed with n two-node beam
// elements (BEAM2). Physical groups become choc's element block and node sets:
//   BAR   (curve)  the element block, and a node set holding every node of the bar;
//   CLAMP (point)  the node at x = 0, clamped in the input;
//   TIP   (point)  the free end at x = L, the node the history records.
// Regenerate (from this directory):  gmsh -1 -format msh41 bar.geo -o bar.msh
// Another mesh density:               gmsh -1 -format msh41 -setnumber n 25 bar.geo -o bar.msh
If (!Exists(n))
  n = 100;
EndIf
L = 1.0;
Point(1) = {0, 0, 0, L};
Point(2) = {L, 0, 0, L};
Line(1) = {1, 2};
Transfinite Curve{1} = n + 1;   // n equal elements (n + 1 nodes)
Physical Curve("BAR") = {1};
Physical Point("CLAMP") = {1};
Physical Point("TIP") = {2};
