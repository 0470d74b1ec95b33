// Example 07: a slice of a thick-walled tube as an axisymmetric section: x = r is the radius,
// y the axis. Inner radius a = 0.05 m, outer radius b = 0.1 m, height H = 0.02 m; nr x ny
// serendipity QUAD8 elements (default 8 x 2), finer towards the bore where the stress varies
// fastest. Physical groups:
//   TUBE    (surface)  the element block (a node set too);
//   INNER   (curve)    the bore r = a: the side set the internal pressure acts on;
//   OUTER   (curve)    the outer surface r = b (free);
//   ENDS    (curves)   the two edges y = 0 and y = H, held axially (plane strain);
//   P_INNER (point)    the node (a, 0); P_OUTER (point) the node (b, 0).
// Regenerate (from this directory):
//   gmsh -2 -order 2 -format msh41 tube.geo -o tube.msh
// Mesh.SecondOrderIncomplete = 1 makes 8-node quadrilaterals (QUAD8), which choc reads; the
// complete 9-node QUAD9 it does not.
a = 0.05;
b = 0.1;
H = 0.02;
If (!Exists(nr))
  nr = 8;
EndIf
If (!Exists(ny))
  ny = 2;
EndIf
Mesh.SecondOrderIncomplete = 1;
Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, H, 0}; Point(4) = {a, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};   // counter-clockwise in the (r, y) plane
Plane Surface(1) = {1};
Transfinite Curve{1} = nr + 1 Using Progression 1.1;   // from r = a outwards: finer at the bore
Transfinite Curve{3} = nr + 1 Using Progression 1 / 1.1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("TUBE") = {1};
Physical Curve("INNER") = {4};
Physical Curve("OUTER") = {2};
Physical Curve("ENDS") = {1, 3};
Physical Point("P_INNER") = {1};
Physical Point("P_OUTER") = {2};
