// Hertz impact in 3D (docs/verification/hertz.md): the quarter x >= 0, z >= 0 of the steel sphere of
// radius R = 10 mm, centre C = (0, R, 0), lowest point O = (0, 0, 0) touching the rigid plane
// y = 0 (given in input/hertz_3d.xml as an obstacle). The planes x = 0 (XSYM) and z = 0 (ZSYM)
// are symmetry planes. The sphere is cut at its equator y = R into two volumes meshed
// conformingly, so that CONTACT is the lower curved quarter only. Quadratic tetrahedra (TET10
// with -order 2, midside nodes on the sphere), of size h near O (default 0.1 mm, about 8
// across the 0.81 mm contact radius) growing to H (default 1.5 mm) beyond 4 mm from O.
// meshes/make-meshes.sh:
//   gmsh -3 -order 2 -format msh41 meshes/hertz_quarter.geo -o meshes/hertz_quarter.msh
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 1e-4;
EndIf
If (!Exists(H))
  H = 1.5e-3;
EndIf
R = 0.01;
Sphere(1) = {0, R, 0, R};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = {Volume{1}; }{ Volume{2}; Delete; };
Box(4) = {0, R, 0, R, R, R};
BooleanIntersection(5) = {Volume{1}; Delete; }{ Volume{4}; Delete; };
BooleanFragments{ Volume{3, 5}; Delete; }{}
// Entities by their bounding boxes (OpenCASCADE widens them by about 1e-7 m).
e = 1e-6;
xs[] = Surface In BoundingBox{-e, -e, -e, e, 2 * R + e, R + e};
zs[] = Surface In BoundingBox{-e, -e, -e, R + e, 2 * R + e, e};
equator[] = Surface In BoundingBox{-e, R - e, -e, R + e, R + e, R + e};
lower[] = Surface In BoundingBox{-e, -e, -e, R + e, R + e, R + e};
lower[] -= {xs[], zs[], equator[]};
O[] = Point In BoundingBox{-e, -e, -e, e, e, e};
C[] = Point In BoundingBox{-e, R - e, -e, e, R + e, e};
Field[1] = Distance;
Field[1].PointsList = {O[0]};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 1.2e-3;
Field[2].DistMax = 4e-3;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("SPHERE") = Volume{:};
Physical Surface("CONTACT") = {lower[]};
Physical Surface("XSYM") = {xs[]};
Physical Surface("ZSYM") = {zs[]};
Physical Point("O") = {O[]};
Physical Point("C") = {C[]};
