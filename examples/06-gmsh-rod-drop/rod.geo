// Example 06: a steel rod, a cylinder of radius R = 5 mm and length L = 50 mm along z, its
// lower face at z = 0, built with gmsh's OpenCASCADE kernel and meshed in quadratic
// tetrahedra (TET10) of size about h.
// Physical groups (the names the input uses):
//   ROD    (volume)   the element block; also a node set of every node;
//   BOTTOM (surface)  the flat lower face z = 0: the contact surface (a side set, TRI6 faces);
//   TOP    (surface)  the flat upper face z = L (a side set and node set, for the history).
// Regenerate (from this directory):
//   gmsh -3 -order 2 -format msh41 rod.geo -o rod.msh
// Another size: add -setnumber h 0.002 (finer) or -setnumber h 0.004 (coarser).
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.003;
EndIf
R = 0.005;
L = 0.05;
Cylinder(1) = {0, 0, 0, 0, 0, L, R};
// The faces by where they are (robust to the kernel's numbering).
eps = 1e-6;
bottom[] = Surface In BoundingBox {-R - eps, -R - eps, -eps, R + eps, R + eps, eps};
top[] = Surface In BoundingBox {-R - eps, -R - eps, L - eps, R + eps, R + eps, L + eps};
Physical Volume("ROD") = {1};
Physical Surface("BOTTOM") = {bottom[]};
Physical Surface("TOP") = {top[]};
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h / 2;
Mesh.Optimize = 1;
Mesh.HighOrderOptimize = 1;   // keeps the curved quadratic elements valid
