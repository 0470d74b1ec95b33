// A steel L-bracket for the drop tests (input/bracket_drop.xml, tools/bench/bench_bracket.py): an
// L profile in the plane y = 0 extruded by W = 40 mm along y. Its base plate lies on z in
// [0, t] for x in [0, L], its upright plate on x in [0, t] for z in [0, L] (L = 60 mm, t = 6 mm),
// with a fillet of radius 6 mm inside the corner and a hole of diameter 10 mm through each plate.
// Quadratic tetrahedra (TET10 with -order 2) of size h (default 3.7 mm: 19,434 unknowns;
// h = 1.5 mm: about 200,000). Physical groups: BRACKET (the volume), SURFACE (every face: the
// contact surface), CORNER (the vertex (L, 0, 0)), TIP (the vertex (0, 0, L)).
// meshes/make-meshes.sh:
//   gmsh -3 -order 2 -format msh41 meshes/bracket.geo -o meshes/bracket.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 3.7e-3;
EndIf
L = 0.06;
t = 0.006;
W = 0.04;
rf = 0.006;
Box(1) = {0, 0, 0, L, W, t};
Box(2) = {0, 0, 0, t, W, L};
BooleanUnion(3) = {Volume{1}; Delete; }{ Volume{2}; Delete; };
// The fillet: the square t..t+rf in the corner less its quarter disc.
Box(4) = {t, 0, t, rf, W, rf};
Cylinder(5) = {t + rf, 0, t + rf, 0, W, 0, rf};
BooleanDifference(6) = {Volume{4}; Delete; }{ Volume{5}; Delete; };
BooleanUnion(7) = {Volume{3}; Delete; }{ Volume{6}; Delete; };
Cylinder(8) = {0.04, W / 2, -0.001, 0, 0, t + 0.002, 0.005};
Cylinder(9) = {-0.001, W / 2, 0.04, t + 0.002, 0, 0, 0.005};
BooleanDifference(10) = {Volume{7}; Delete; }{ Volume{8, 9}; Delete; };
e = 1e-6;
CORNER[] = Point In BoundingBox{L - e, -e, -e, L + e, e, e};
TIP[] = Point In BoundingBox{-e, -e, L - e, e, e, L + e};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Physical Volume("BRACKET") = {10};
Physical Surface("SURFACE") = Surface{:};
Physical Point("CORNER") = {CORNER[]};
Physical Point("TIP") = {TIP[]};
