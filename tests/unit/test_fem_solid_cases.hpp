// Single-element test geometries for the continuum elements, each with its exact measure
// computed here in closed form (independent of the element code): volume (3D), area
// (plane strain), 2 pi int r dA (axisymmetric).
#pragma once
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "fem/Kinematics.hpp"
#include "test_fem_helpers.hpp"

namespace choc::test {

constexpr double kPi = 3.14159265358979323846;

using EdgeList = std::vector<std::pair<int, int>>;  // 0-based corners, Exodus order

inline const EdgeList& exodusEdges(const std::string& topology) {
  static const EdgeList tri = {{0, 1}, {1, 2}, {2, 0}}, quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const EdgeList tet = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  static const EdgeList hex = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                               {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static const EdgeList none;
  if (topology == "TRI6") return tri;
  if (topology == "QUAD8") return quad;
  if (topology == "TET10") return tet;
  if (topology == "HEX20") return hex;
  return none;
}

inline Point3 midpoint(const Point3& a, const Point3& b) {
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

inline Point3 add3(const Point3& a, const Point3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Point3 sub3(const Point3& a, const Point3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Corner nodes plus straight mid-edge nodes for a quadratic topology.
inline std::vector<Point3> withMidEdgeNodes(const std::string& topology, std::vector<Point3> x) {
  const std::vector<Point3> corners = x;
  for (const auto& [a, b] : exodusEdges(topology)) x.push_back(midpoint(corners[a], corners[b]));
  return x;
}

struct ElementCase {
  std::string label;     // gtest parameter name
  std::string topology;  // canonical Exodus name
  Kinematics kinematics;
  std::vector<Point3> x;
  double measure;  // exact volume / area / ring volume
};

// gtest prints a parameter by this; ctest then names the test .../<label> (the gtest name is
// .../<index>).
inline void PrintTo(const ElementCase& c, std::ostream* os) { *os << c.label; }

// ---- 2D: straight-sided polygons, exact area and int r dA by Green's theorem ----

// Area of the polygon (counter-clockwise) and int x dA over it (x = r for axisymmetric).
inline double polygonArea(const std::vector<Point3>& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point3 &u = p[i], &v = p[(i + 1) % p.size()];
    a += (v[1] - u[1]) * (u[0] + v[0]) / 2;
  }
  return a;
}

inline double polygonFirstMoment(const std::vector<Point3>& p) {
  double m = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point3 &u = p[i], &v = p[(i + 1) % p.size()];
    m += (v[1] - u[1]) * (u[0] * u[0] + u[0] * v[0] + v[0] * v[0]) / 6;
  }
  return m;
}

inline double planeMeasure(Kinematics k, const std::vector<Point3>& corners) {
  return k == Kinematics::Axisymmetric ? 2 * kPi * polygonFirstMoment(corners)
                                       : polygonArea(corners);
}

// Moving the mid-edge node of straight edge (a, b) by d adds d . (outward normal) * 2/3 L:
// with x = x0 + d N_m, det J is linear in d and int grad N_m dA = int_edge N_m n ds, and
// N_m integrates to 2/3 of the edge length along its edge (4 L_a L_b or 1 - s^2).
inline double curvedEdgeArea(const Point3& a, const Point3& b, const Point3& d) {
  return 2.0 / 3 * (d[0] * (b[1] - a[1]) - d[1] * (b[0] - a[0]));
}

inline std::vector<ElementCase> planeCases(Kinematics k, const char* kin) {
  const std::string s = kin;
  std::vector<ElementCase> c;
  const double r0 = k == Kinematics::Axisymmetric ? 1.0 : 0.1;  // away from the axis
  const std::vector<Point3> tri = {{r0, 0.2, 0}, {r0 + 1.2, 0.4, 0}, {r0 + 0.4, 1.2, 0}};
  // Parallelogram (affine) and a general convex quadrilateral (not affine).
  const Point3 o = {r0 + 0.1, 0.1, 0}, ea = {1.1, 0.2, 0}, eb = {0.3, 0.9, 0};
  const std::vector<Point3> par = {o, add3(o, ea), add3(add3(o, ea), eb), add3(o, eb)};
  const std::vector<Point3> quad = {
      {r0, 0.0, 0}, {r0 + 1.2, 0.2, 0}, {r0 + 1.4, 1.3, 0}, {r0 - 0.1, 0.9, 0}};
  for (const char* topo : {"TRI3", "TRI6"})
    c.push_back({std::string(topo) + "_" + s + "_affine", topo, k, withMidEdgeNodes(topo, tri),
                 planeMeasure(k, tri)});
  for (const char* topo : {"QUAD4", "QUAD8"}) {
    c.push_back({std::string(topo) + "_" + s + "_affine", topo, k, withMidEdgeNodes(topo, par),
                 planeMeasure(k, par)});
    c.push_back({std::string(topo) + "_" + s + "_distorted", topo, k, withMidEdgeNodes(topo, quad),
                 planeMeasure(k, quad)});
  }
  return c;
}

// Elements touching the axis (nodes at r = 0) and the rectangle of the closed-form
// axisymmetric energy: int r dA = (r1^2 - r0^2) / 2 (z1 - z0).
inline std::vector<ElementCase> axisymmetricExtraCases() {
  const Kinematics k = Kinematics::Axisymmetric;
  std::vector<ElementCase> c;
  const std::vector<Point3> tri = {{0, 0, 0}, {1.2, 0.1, 0}, {0, 1.0, 0}};
  const std::vector<Point3> quad = {{0, 0, 0}, {1.1, 0.1, 0}, {1.3, 1.2, 0}, {0, 1.0, 0}};
  const double ra = 1.0, rb = 2.0, za = 0.5, zb = 1.7;
  const std::vector<Point3> rect = {{ra, za, 0}, {rb, za, 0}, {rb, zb, 0}, {ra, zb, 0}};
  const double ring = 2 * kPi * (rb * rb - ra * ra) / 2 * (zb - za);
  for (const char* topo : {"TRI3", "TRI6"})
    c.push_back({std::string(topo) + "_axi_on_axis", topo, k, withMidEdgeNodes(topo, tri),
                 planeMeasure(k, tri)});
  for (const char* topo : {"QUAD4", "QUAD8"}) {
    c.push_back({std::string(topo) + "_axi_on_axis", topo, k, withMidEdgeNodes(topo, quad),
                 planeMeasure(k, quad)});
    c.push_back(
        {std::string(topo) + "_axi_rectangle", topo, k, withMidEdgeNodes(topo, rect), ring});
  }
  return c;
}

// Quadratic plane-strain elements with one curved edge (mid-edge node of edge 1-2 moved).
inline std::vector<ElementCase> curvedPlaneCases() {
  std::vector<ElementCase> c;
  const Point3 d = {0.04, -0.09, 0};
  for (const ElementCase& e : planeCases(Kinematics::PlaneStrain, "plane")) {
    if (e.topology != "TRI6" && e.topology != "QUAD8") continue;
    ElementCase curved = e;
    const int corners = e.topology == "TRI6" ? 3 : 4;
    curved.x[corners] = add3(curved.x[corners], d);
    curved.measure += curvedEdgeArea(e.x[0], e.x[1], d);
    curved.label += "_curved";
    c.push_back(curved);
  }
  return c;
}

// ---- 3D ----

inline double tetVolume(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return dot3(sub3(b, a), cross3(sub3(c, a), sub3(d, a))) / 6;
}

// Outward area vector of the planar face q (3 or 4 points, parallelogram when 4) of a
// convex body with interior point inside.
inline Point3 outwardArea(const std::vector<Point3>& q, const Point3& inside) {
  Point3 s = cross3(sub3(q[1], q[0]), sub3(q.back(), q[0]));
  if (q.size() == 3)
    for (double& v : s) v /= 2;
  if (dot3(s, sub3(q[0], inside)) < 0)
    for (double& v : s) v = -v;
  return s;
}

// A prism over [0, sx] x [0, sy] with a bilinear (non-planar) top at heights h, mapped by
// x -> R S x + t: not affine, volume det(S) sx sy mean(h) (the height is bilinear).
inline std::vector<Point3> distortedHexCorners(double& volume) {
  const double sx = 0.9, sy = 1.2, h[4] = {1.0, 1.3, 0.8, 1.15};
  const double base[4][2] = {{0, 0}, {sx, 0}, {sx, sy}, {0, sy}};
  const double S[3][3] = {{1.1, 0.2, 0.1}, {0.0, 0.9, -0.15}, {0.0, 0.0, 1.05}};
  const auto R = someRotation();
  std::vector<Point3> x;
  for (int layer = 0; layer < 2; ++layer)
    for (int a = 0; a < 4; ++a) {
      const Point3 p = {base[a][0], base[a][1], layer ? h[a] : 0.0};
      Point3 q;
      for (int i = 0; i < 3; ++i) q[i] = S[i][0] * p[0] + S[i][1] * p[1] + S[i][2] * p[2];
      x.push_back(add3(rotate(R, q), {0.4, -1.1, 2.3}));
    }
  volume = 1.1 * 0.9 * 1.05 * sx * sy * (h[0] + h[1] + h[2] + h[3]) / 4;
  return x;
}

// The parallelepiped x = o + R S c, c in the unit cube: affine, volume det(S).
inline std::vector<Point3> affineHexCorners(double& volume) {
  const double S[3][3] = {{0.8, 0.15, -0.1}, {0.0, 1.1, 0.2}, {0.0, 0.0, 0.7}};
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const auto R = someRotation();
  std::vector<Point3> x;
  for (const auto& p : c) {
    Point3 q;
    for (int i = 0; i < 3; ++i) q[i] = S[i][0] * p[0] + S[i][1] * p[1] + S[i][2] * p[2];
    x.push_back(add3(rotate(R, q), {-0.3, 0.6, 1.2}));
  }
  volume = 0.8 * 1.1 * 0.7;
  return x;
}

// Moving the mid-edge node of a straight edge by d changes the volume by d . (S1 + S2) / 3,
// S1, S2 the outward area vectors of the two planar faces sharing the edge (N_m integrates
// to a third of each face's area on it, for TET10 and for HEX20 on parallelograms).
inline double curvedEdgeVolume(const Point3& d, const Point3& s1, const Point3& s2) {
  return dot3(d, add3(s1, s2)) / 3;
}

inline std::vector<ElementCase> solidCases3D() {
  const Kinematics k = Kinematics::ThreeD;
  std::vector<ElementCase> c;
  const std::vector<Point3> tet = {
      {0.1, 0.2, -0.3}, {1.3, 0.15, -0.1}, {0.4, 1.1, 0.05}, {0.2, 0.35, 0.9}};
  const double vt = tetVolume(tet[0], tet[1], tet[2], tet[3]);
  c.push_back({"TET4_3D_affine", "TET4", k, tet, vt});
  c.push_back({"TET10_3D_affine", "TET10", k, withMidEdgeNodes("TET10", tet), vt});
  const Point3 d = {0.05, -0.07, 0.06};
  Point3 centre = {0, 0, 0};
  for (const Point3& p : tet) centre = add3(centre, {p[0] / 4, p[1] / 4, p[2] / 4});
  ElementCase curvedTet = c.back();
  curvedTet.label = "TET10_3D_curved";
  curvedTet.x[4] = add3(curvedTet.x[4], d);  // node 5, edge (1, 2): faces 1-2-3 and 1-2-4
  curvedTet.measure += curvedEdgeVolume(d, outwardArea({tet[0], tet[1], tet[2]}, centre),
                                        outwardArea({tet[0], tet[1], tet[3]}, centre));
  c.push_back(curvedTet);
  double va = 0.0, vd = 0.0;
  const std::vector<Point3> par = affineHexCorners(va), dist = distortedHexCorners(vd);
  for (const char* topo : {"HEX8", "HEX20"}) {
    c.push_back({std::string(topo) + "_3D_affine", topo, k, withMidEdgeNodes(topo, par), va});
    c.push_back({std::string(topo) + "_3D_distorted", topo, k, withMidEdgeNodes(topo, dist), vd});
  }
  ElementCase curvedHex = c[c.size() - 2];  // HEX20 affine, node 9 (edge 1-2) moved
  curvedHex.label = "HEX20_3D_curved";
  curvedHex.x[8] = add3(curvedHex.x[8], d);
  Point3 hc = {0, 0, 0};
  for (int a = 0; a < 8; ++a) hc = add3(hc, {par[a][0] / 8, par[a][1] / 8, par[a][2] / 8});
  curvedHex.measure += curvedEdgeVolume(d, outwardArea({par[0], par[1], par[2], par[3]}, hc),
                                        outwardArea({par[0], par[1], par[5], par[4]}, hc));
  c.push_back(curvedHex);
  return c;
}

inline std::vector<ElementCase> allElementCases() {
  std::vector<ElementCase> c = solidCases3D();
  for (const auto& group : {planeCases(Kinematics::PlaneStrain, "plane"), curvedPlaneCases(),
                            planeCases(Kinematics::Axisymmetric, "axi"), axisymmetricExtraCases()})
    c.insert(c.end(), group.begin(), group.end());
  return c;
}

}  // namespace choc::test
