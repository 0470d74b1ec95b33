// The thick-walled hollow sphere of meshes/thick_sphere_axisymmetric.geo in 3D: the octant x, y,
// z >= 0 of the shell A = 50 mm <= |x| <= B = 100 mm, the three coordinate planes symmetry
// planes. Tetrahedra of size h (default 12.5 mm, four across the wall); TET10 with -order 2.
//   gmsh -3 -order 2 -format msh41 -setnumber h 0.00625 meshes/thick_sphere_octant.geo -o s.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.0125;
EndIf
A = 0.05;
B = 0.1;
Sphere(1) = {0, 0, 0, B, 0, Pi / 2, Pi / 2};
Sphere(2) = {0, 0, 0, A, 0, Pi / 2, Pi / 2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
e = 1e-6;
inner[] = Surface In BoundingBox{-e, -e, -e, A + e, A + e, A + e};
x0[] = Surface In BoundingBox{-e, -e, -e, e, B + e, B + e};
y0[] = Surface In BoundingBox{-e, -e, -e, B + e, e, B + e};
z0[] = Surface In BoundingBox{-e, -e, -e, B + e, B + e, e};
px[] = Point In BoundingBox{A - e, -e, -e, A + e, e, e};
pz[] = Point In BoundingBox{-e, -e, A - e, e, e, A + e};
qx[] = Point In BoundingBox{B - e, -e, -e, B + e, e, e};
Physical Volume("SPHERE") = {3};
Physical Surface("INNER") = {inner[]};
Physical Surface("X0") = {x0[]};
Physical Surface("Y0") = {y0[]};
Physical Surface("Z0") = {z0[]};
Physical Point("INNER_X") = {px[]};
Physical Point("INNER_Z") = {pz[]};
Physical Point("OUTER_X") = {qx[]};
