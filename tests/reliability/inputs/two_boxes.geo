// Two steel cubes of 1 cm stacked along z, meshed apart: their nodes meet at z = 1 cm without
// being shared (the common gmsh mistake of two volumes without "Coherence"). HEX8, 2 x 2 x 2
// per cube. gmsh -3 two_boxes.geo -o two_boxes.msh
Geometry.AutoCoherence = 0;
h = 0.01;
n = 3;
For k In {0:1}
  z = k * h;
  p = newp;
  Point(p) = {0, 0, z}; Point(p + 1) = {h, 0, z}; Point(p + 2) = {h, h, z}; Point(p + 3) = {0, h, z};
  l = newl;
  Line(l) = {p, p + 1}; Line(l + 1) = {p + 1, p + 2}; Line(l + 2) = {p + 2, p + 3}; Line(l + 3) = {p + 3, p};
  Transfinite Curve{l:l + 3} = n;
  c = newll;
  Curve Loop(c) = {l:l + 3};
  s = news;
  Plane Surface(s) = {c};
  Transfinite Surface{s};
  Recombine Surface{s};
  out[] = Extrude {0, 0, h} { Surface{s}; Layers{2}; Recombine; };
  bottom[k] = s;
  volume[k] = out[1];
  top[k] = out[0];
EndFor
Physical Volume("lower") = {volume[0]};
Physical Volume("upper") = {volume[1]};
Physical Surface("base") = {bottom[0]};
Physical Surface("top") = {top[1]};
