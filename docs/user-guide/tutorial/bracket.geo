// An L-shaped steel bracket for the tutorial (docs/user-guide/tutorial.md).
// A foot 40 x 20 x 10 mm lying on z = 0 and an upright 10 x 20 x 30 mm standing on its
// x = 0 end, meshed in TET4. Lengths in metres.
//   gmsh -3 docs/user-guide/tutorial/bracket.geo -o docs/user-guide/tutorial/bracket.msh
SetFactory("OpenCASCADE");
h = 0.0025;                                 // element size [m]
Box(1) = {0, 0, 0, 0.04, 0.02, 0.01};       // the foot
Box(2) = {0, 0, 0.01, 0.01, 0.02, 0.03};    // the upright
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.CharacteristicLengthMax = h;
e = 1e-6;
// Physical groups become what the input names: the volume an element block (and a node set),
// a surface a side set (and a node set), a point a node set.
Physical Volume("BRACKET") = Volume{:};
Physical Surface("BOTTOM") = Surface In BoundingBox{-e, -e, -e, 0.04 + e, 0.02 + e, e};
Physical Point("HEEL") = Point In BoundingBox{0.04 - e, -e, -e, 0.04 + e, e, e};
Physical Point("TIP") = Point In BoundingBox{-e, -e, 0.04 - e, e, e, 0.04 + e};
