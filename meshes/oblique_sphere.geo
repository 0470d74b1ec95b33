// An elastic sphere hitting a rigid plane obliquely (input/oblique_sphere.xml): the half z >= 0 of
// the steel sphere of radius R = 10 mm, centre C = (0, R, 0), lowest point O = (0, 0, 0) touching
// the plane y = 0; it moves in the plane z = 0 (ZSYM, a symmetry plane). The sphere is cut at its
// equator y = R into two volumes meshed conformingly, so that CONTACT is the lower half-hemisphere
// only. Quadratic tetrahedra (TET10 with -order 2), of size h near O (default 0.35 mm, about 4
// across the 0.6 mm contact radius) growing to H (default 3 mm) beyond 4 mm from O: 6,500
// unknowns; with -setnumber h 2e-4 -setnumber H 2.5e-3, 17,600.
// meshes/make-meshes.sh:
//   gmsh -3 -order 2 -format msh41 meshes/oblique_sphere.geo -o meshes/oblique_sphere.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 3.5e-4;
EndIf
If (!Exists(H))
  H = 3e-3;
EndIf
R = 0.01;
Sphere(1) = {0, R, 0, R};
Box(2) = {-R, 0, 0, 2 * R, R, R};
BooleanIntersection(3) = {Volume{1}; }{ Volume{2}; Delete; };
Box(4) = {-R, R, 0, 2 * R, R, R};
BooleanIntersection(5) = {Volume{1}; Delete; }{ Volume{4}; Delete; };
Point(100) = {0, R, 0};  // the centre, on the edge where the equator meets z = 0: a vertex
BooleanFragments{ Volume{3, 5}; Point{100}; Delete; }{}
// Entities by their bounding boxes (OpenCASCADE widens them by about 1e-7 m).
e = 1e-6;
zs[] = Surface In BoundingBox{-R - e, -e, -e, R + e, 2 * R + e, e};
equator[] = Surface In BoundingBox{-R - e, R - e, -e, R + e, R + e, R + e};
lower[] = Surface In BoundingBox{-R - e, -e, -e, R + e, R + e, R + e};
lower[] -= {zs[], equator[]};
O[] = Point In BoundingBox{-e, -e, -e, e, e, e};
C[] = Point In BoundingBox{-e, R - e, -e, e, R + e, e};
Field[1] = Distance;
Field[1].PointsList = {O[0]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 1.5e-3;
Field[2].DistMax = 4e-3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("SPHERE") = Volume{:};
Physical Surface("CONTACT") = {lower[]};
Physical Surface("ZSYM") = {zs[]};
Physical Point("O") = {O[]};
Physical Point("C") = {C[]};
