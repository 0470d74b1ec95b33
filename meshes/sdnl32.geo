// SDNL32 (docs/verification/sdnl32.md): the articulated beam, 10 two-node Timoshenko elements
// along x with the deck's node coordinates (node 7 at 0.462 m, off the regular spacing); node sets N1..N11.
// gmsh -1 -format msh41 sdnl32.geo -o sdnl32.msh
Point(1) = {0, 0, 0, 1};
Point(2) = {0.0783, 0, 0, 1};
Point(3) = {0.1566, 0, 0, 1};
Point(4) = {0.2349, 0, 0, 1};
Point(5) = {0.3132, 0, 0, 1};
Point(6) = {0.3915, 0, 0, 1};
Point(7) = {0.462, 0, 0, 1};
Point(8) = {0.5481, 0, 0, 1};
Point(9) = {0.6264, 0, 0, 1};
Point(10) = {0.7047, 0, 0, 1};
Point(11) = {0.783, 0, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 9};
Line(9) = {9, 10};
Line(10) = {10, 11};
Transfinite Curve{1:10} = 2;
Physical Curve("BEAM") = {1:10};
Physical Point("N1") = {1};
Physical Point("N2") = {2};
Physical Point("N3") = {3};
Physical Point("N4") = {4};
Physical Point("N5") = {5};
Physical Point("N6") = {6};
Physical Point("N7") = {7};
Physical Point("N8") = {8};
Physical Point("N9") = {9};
Physical Point("N10") = {10};
Physical Point("N11") = {11};
