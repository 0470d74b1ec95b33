// A whole ball for the 3D rubber-ball scenes (tests/cli/scripts/rubber_ball_frame.py): radius
// R = 10 mm centred at C = (0, R, 0), so that its lowest point O = (0, 0, 0) touches the plane
// y = 0. Tetrahedra of size h (default 3 mm); TET10 with -order 2. 'SPHERE' the volume, 'CONTACT'
// its surface (the contact side), 'C' the centre node (embedded).
//   gmsh -3 -order 2 -format msh41 meshes/rubber_ball_3d.geo -o ball.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.003;
EndIf
R = 0.01;
Sphere(1) = {0, R, 0, R};
Point(100) = {0, R, 0};
Point{100} In Volume{1};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Physical Volume("SPHERE") = {1};
Physical Surface("CONTACT") = {Boundary{Volume{1};}};
Physical Point("C") = {100};
