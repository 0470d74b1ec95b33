// SDNL111's two bars as a 2D section in the x-y plane (plane strain, or axisymmetric with x = r
// and y the axis): width 0.02 (x in [0, 0.02]), bar 1 (POU1, A..B) from y = 1e-5 to 1.00001,
// bar 2 (POU2, C..D) from y = -1 to 0; 1 element across and n (default 50) along each bar,
// quadrilaterals (QUAD4; QUAD8 with -order 2), or with quad = 0 triangles (TRI3; TRI6). The
// physical names are those of the 3D meshes; the contact sides are curves. meshes/make-meshes.sh
// generates the committed QUAD8 mesh:
//   gmsh -2 -order 2 -format msh41 meshes/sdnl111_2d.geo -o meshes/sdnl111_2d_quad8.msh
// tools/study/bar_convergence.py meshes the other element types and refinements, for example
//   gmsh -2 -order 1 -setnumber n 100 -setnumber quad 0 -format msh41 sdnl111_2d.geo -o s.msh
a = 0.02;
L = 1.0;
g = 1e-5;
If (!Exists(n))
  n = 50;
EndIf
Mesh.SecondOrderIncomplete = 1;

Point(1) = {0, g, 0}; Point(2) = {a, g, 0}; Point(3) = {a, g + L, 0}; Point(4) = {0, g + L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};  // counter-clockwise: outward normals of the element edges
Plane Surface(1) = {1};

Point(11) = {0, -L, 0}; Point(12) = {a, -L, 0}; Point(13) = {a, 0, 0}; Point(14) = {0, 0, 0};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};

Transfinite Curve{1, 3, 11, 13} = 2;
Transfinite Curve{2, 4, 12, 14} = n + 1;
Transfinite Surface{1, 11};
If (!Exists(quad))
  quad = 1;
EndIf
If (quad)
  Recombine Surface{1, 11};
EndIf

Physical Surface("POU1") = {1};
Physical Surface("POU2") = {11};
Physical Curve("CNT_POU1") = {1};   // bar 1's edge at y = g (master)
Physical Curve("CNT_POU2") = {13};  // bar 2's edge at y = 0 (slave)
Physical Curve("CL_POU2") = {11};   // bar 2's edge at y = -L (clamped)
Physical Point("N1") = {1};         // point A, on the axis x = 0
