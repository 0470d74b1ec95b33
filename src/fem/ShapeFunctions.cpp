// Shape functions: barycentric polynomials on simplices, (serendipity) tensor products on
// boxes. The quadratic topologies are described by their corner topology plus one mid-edge
// node per edge, listed in Exodus order.
#include "fem/ShapeFunctions.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace choc {

namespace {

using Edges = std::vector<std::pair<int, int>>;  // 0-based corner pairs, Exodus order

struct TopologyInfo {
  SolidShape topology;
  const char* name;
  int dim;
  bool simplex;
  int corners;
  Edges edges;  // empty for the linear topologies
  int nodes() const { return corners + static_cast<int>(edges.size()); }
};

const Edges kTriEdges = {{0, 1}, {1, 2}, {2, 0}};
const Edges kQuadEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const Edges kTetEdges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
const Edges kHexEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                         {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};

const std::vector<TopologyInfo>& table() {
  static const std::vector<TopologyInfo> t = {
      {SolidShape::Tet4, "TET4", 3, true, 4, {}},
      {SolidShape::Tet10, "TET10", 3, true, 4, kTetEdges},
      {SolidShape::Hex8, "HEX8", 3, false, 8, {}},
      {SolidShape::Hex20, "HEX20", 3, false, 8, kHexEdges},
      {SolidShape::Tri3, "TRI3", 2, true, 3, {}},
      {SolidShape::Tri6, "TRI6", 2, true, 3, kTriEdges},
      {SolidShape::Quad4, "QUAD4", 2, false, 4, {}},
      {SolidShape::Quad8, "QUAD8", 2, false, 4, kQuadEdges},
  };
  return t;
}

const TopologyInfo& info(SolidShape t) { return table().at(static_cast<size_t>(t)); }

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::vector<Point3> naturalCoordinates(const TopologyInfo& ti) {
  std::vector<Point3> p;
  if (ti.simplex) {
    p.push_back({0, 0, 0});
    for (int k = 0; k < ti.dim; ++k) {
      Point3 v = {0, 0, 0};
      v[k] = 1;
      p.push_back(v);
    }
  } else {
    const double square[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int layer = 0; layer < (ti.dim == 3 ? 2 : 1); ++layer)
      for (const auto& c : square)
        p.push_back({c[0], c[1], ti.dim == 3 ? (layer == 0 ? -1.0 : 1.0) : 0.0});
  }
  for (const auto& [a, b] : ti.edges)
    p.push_back({(p[a][0] + p[b][0]) / 2, (p[a][1] + p[b][1]) / 2, (p[a][2] + p[b][2]) / 2});
  return p;
}

// Simplex: barycentric L_0 = 1 - sum xi, L_k = xi_(k-1). Linear N_a = L_a; quadratic corners
// L_a (2 L_a - 1), mid-edge (a, b) 4 L_a L_b.
void simplexShape(const TopologyInfo& ti, const Point3& xi, std::vector<double>& N,
                  std::vector<Point3>& dN) {
  double L[4];
  Point3 dL[4];
  L[0] = 1.0;
  dL[0] = {0, 0, 0};
  for (int k = 0; k < ti.dim; ++k) {
    L[0] -= xi[k];
    dL[0][k] = -1.0;
    L[k + 1] = xi[k];
    dL[k + 1] = {0, 0, 0};
    dL[k + 1][k] = 1.0;
  }
  const bool quadratic = !ti.edges.empty();
  for (int a = 0; a < ti.corners; ++a) {
    N[a] = quadratic ? L[a] * (2 * L[a] - 1) : L[a];
    const double f = quadratic ? 4 * L[a] - 1 : 1.0;
    for (int i = 0; i < 3; ++i) dN[a][i] = f * dL[a][i];
  }
  for (size_t e = 0; e < ti.edges.size(); ++e) {
    const auto [a, b] = ti.edges[e];
    const size_t n = ti.corners + e;
    N[n] = 4 * L[a] * L[b];
    for (int i = 0; i < 3; ++i) dN[n][i] = 4 * (L[b] * dL[a][i] + L[a] * dL[b][i]);
  }
}

// Box node with natural coordinates c: f_i = (1 + c_i xi_i) / 2 for c_i != 0. Corner of a
// linear box: prod f_i. Serendipity corner: prod f_i (sum c_i xi_i - (dim - 1)). Serendipity
// mid-edge node along direction m (c_m = 0): (1 - xi_m^2) prod_(i != m) f_i.
void boxNodeShape(int dim, bool serendipity, const Point3& c, const Point3& xi, double& N,
                  Point3& dN) {
  double f[3], df[3];
  int m = -1;
  for (int i = 0; i < dim; ++i) {
    if (c[i] == 0.0) {
      m = i;
      f[i] = 1 - xi[i] * xi[i];
      df[i] = -2 * xi[i];
    } else {
      f[i] = (1 + c[i] * xi[i]) / 2;
      df[i] = c[i] / 2;
    }
  }
  double s = 1.0, ds[3] = {0, 0, 0};  // the serendipity corner factor and its gradient
  if (serendipity && m < 0) {
    s = 1.0 - dim;
    for (int i = 0; i < dim; ++i) {
      s += c[i] * xi[i];
      ds[i] = c[i];
    }
  }
  double p = 1.0;
  for (int i = 0; i < dim; ++i) p *= f[i];
  N = p * s;
  dN = {0, 0, 0};
  for (int k = 0; k < dim; ++k) {
    double pk = df[k];  // d(prod f)/dxi_k
    for (int i = 0; i < dim; ++i)
      if (i != k) pk *= f[i];
    dN[k] = pk * s + p * ds[k];
  }
}

}  // namespace

std::vector<std::string> solidTopologies() {
  std::vector<std::string> names;
  for (const TopologyInfo& ti : table()) names.push_back(ti.name);
  return names;
}

const char* topologyName(SolidShape t) { return info(t).name; }

bool findSolidTopology(const std::string& name, SolidShape& topology) {
  static const std::vector<std::pair<const char*, SolidShape>> aliases = {
      {"TETRA", SolidShape::Tet4},    {"TETRA4", SolidShape::Tet4},   {"TET4", SolidShape::Tet4},
      {"TETRA10", SolidShape::Tet10}, {"TET10", SolidShape::Tet10},   {"HEX", SolidShape::Hex8},
      {"HEX8", SolidShape::Hex8},     {"HEX20", SolidShape::Hex20},   {"TRI", SolidShape::Tri3},
      {"TRI3", SolidShape::Tri3},     {"TRIANGLE", SolidShape::Tri3}, {"TRI6", SolidShape::Tri6},
      {"QUAD", SolidShape::Quad4},    {"QUAD4", SolidShape::Quad4},   {"QUAD8", SolidShape::Quad8}};
  const std::string key = upper(name);
  for (const auto& [alias, t] : aliases)
    if (key == alias) {
      topology = t;
      return true;
    }
  return false;
}

SolidShape solidTopology(const std::string& name) {
  SolidShape t;
  if (findSolidTopology(name, t)) return t;
  std::string list;
  for (const std::string& s : solidTopologies()) list += (list.empty() ? "" : ", ") + s;
  throw std::invalid_argument(
      "element topology '" + name +
      "' is not a supported continuum (solid) topology; supported: " + list);
}

int nodeCount(SolidShape t) { return info(t).nodes(); }
int parametricDimension(SolidShape t) { return info(t).dim; }
bool isQuadratic(SolidShape t) { return !info(t).edges.empty(); }
int cornerCount(SolidShape t) { return info(t).corners; }

const std::vector<Point3>& nodeNaturalCoordinates(SolidShape t) {
  static const std::vector<std::vector<Point3>> coords = [] {
    std::vector<std::vector<Point3>> c;
    for (const TopologyInfo& ti : table()) c.push_back(naturalCoordinates(ti));
    return c;
  }();
  return coords.at(static_cast<size_t>(t));
}

void shapeFunctions(SolidShape t, const Point3& xi, std::vector<double>& N, std::vector<Point3>& dN) {
  const TopologyInfo& ti = info(t);
  N.resize(ti.nodes());
  dN.resize(ti.nodes());
  if (ti.simplex) return simplexShape(ti, xi, N, dN);
  const std::vector<Point3>& c = nodeNaturalCoordinates(t);
  for (int a = 0; a < ti.nodes(); ++a)
    boxNodeShape(ti.dim, !ti.edges.empty(), c[a], xi, N[a], dN[a]);
}

const QuadratureRule& stiffnessRule(SolidShape t, Kinematics kinematics) {
  const bool axi = kinematics == Kinematics::Axisymmetric;
  switch (t) {
    case SolidShape::Tet4:
      return tetrahedronRule(1);
    case SolidShape::Tet10:
      return tetrahedronRule(4);
    case SolidShape::Tri3:
      return axi ? triangleRule(7) : triangleRule(1);
    case SolidShape::Tri6:
      return axi ? triangleRule(7) : triangleRule(3);
    default:
      return massRule(t);  // the boxes use the same Gauss product for both
  }
}

const QuadratureRule& massRule(SolidShape t) {
  switch (t) {
    case SolidShape::Tet4:
      return tetrahedronRule(4);
    case SolidShape::Tet10:
      return tetrahedronRule(14);
    case SolidShape::Hex8:
      return gaussBoxRule(3, 2);
    case SolidShape::Hex20:
      return gaussBoxRule(3, 3);
    case SolidShape::Tri3:
    case SolidShape::Tri6:
      return triangleRule(7);
    case SolidShape::Quad4:
      return gaussBoxRule(2, 2);
    case SolidShape::Quad8:
      return gaussBoxRule(2, 3);
  }
  throw std::invalid_argument("massRule: unknown topology");
}

}  // namespace choc
