// Shape functions and quadrature of the isoparametric continuum topologies: Exodus node
// order, Kronecker property, completeness, derivatives, and the exactness of every rule.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

using namespace choc;

namespace {

constexpr double kTol = 1e-12;  // round-off on O(1) polynomial values

using Edges = std::vector<std::pair<int, int>>;

// The Exodus II node order written out independently of the code: corners, then one
// mid-edge node per listed edge (1-based corner numbers, as in the manual).
struct ExodusLayout {
  std::vector<Point3> corners;
  Edges edges;
};

std::map<std::string, ExodusLayout> exodusLayouts() {
  const std::vector<Point3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Point3> hex = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const std::vector<Point3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Point3> quad = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  return {{"TET4", {tet, {}}},
          {"TET10", {tet, {{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}}}},
          {"HEX8", {hex, {}}},
          {"HEX20",
           {hex,
            {{1, 2},
             {2, 3},
             {3, 4},
             {4, 1},
             {1, 5},
             {2, 6},
             {3, 7},
             {4, 8},
             {5, 6},
             {6, 7},
             {7, 8},
             {8, 5}}}},
          {"TRI3", {tri, {}}},
          {"TRI6", {tri, {{1, 2}, {2, 3}, {3, 1}}}},
          {"QUAD4", {quad, {}}},
          {"QUAD8", {quad, {{1, 2}, {2, 3}, {3, 4}, {4, 1}}}}};
}

std::vector<Point3> expectedNodes(const ExodusLayout& l) {
  std::vector<Point3> p = l.corners;
  for (const auto& [a, b] : l.edges) {
    const Point3& u = l.corners[a - 1];
    const Point3& v = l.corners[b - 1];
    p.push_back({(u[0] + v[0]) / 2, (u[1] + v[1]) / 2, (u[2] + v[2]) / 2});
  }
  return p;
}

// A few interior natural points of the reference cell of t.
std::vector<Point3> samplePoints(SolidShape t) {
  const bool simplex =
      t == SolidShape::Tet4 || t == SolidShape::Tet10 || t == SolidShape::Tri3 || t == SolidShape::Tri6;
  const int dim = parametricDimension(t);
  std::vector<Point3> p =
      simplex ? std::vector<Point3>{{0.2, 0.3, 0.1}, {0.05, 0.6, 0.25}, {0.7, 0.1, 0.15}}
              : std::vector<Point3>{{0.3, -0.7, 0.45}, {-0.9, 0.2, -0.35}, {0.65, 0.8, -0.1}};
  if (dim == 2)
    for (Point3& q : p) q[2] = 0.0;
  return p;
}

// Complete polynomials of degree <= 2 in the natural coordinates (all reproduced by every
// topology here, the linear ones only up to degree 1 for the simplices and multilinear for
// the boxes).
double poly(int which, const Point3& x) {
  switch (which) {
    case 0:
      return 1.0;
    case 1:
      return 0.3 * x[0] - 1.2 * x[1] + 0.7 * x[2] + 0.4;
    default:
      return x[0] * x[0] - 0.5 * x[0] * x[1] + 0.8 * x[1] * x[2] + 0.3 * x[2] * x[2];
  }
}

double monomialBox(int e) { return e % 2 ? 0.0 : 2.0 / (e + 1); }

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Integral of xi^i eta^j zeta^k over the unit simplex of dimension dim.
double monomialSimplex(int dim, int i, int j, int k) {
  return factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + dim);
}

double integrate(const QuadratureRule& q, int i, int j, int k) {
  double s = 0.0;
  for (int p = 0; p < q.size(); ++p)
    s += q.weights[p] * std::pow(q.points[p][0], i) * std::pow(q.points[p][1], j) *
         std::pow(q.points[p][2], k);
  return s;
}

void checkRule(const QuadratureRule& q, int dim, bool simplex) {
  const double measure = simplex ? 1.0 / factorial(dim) : std::pow(2.0, dim);
  double wsum = 0.0;
  for (int p = 0; p < q.size(); ++p) {
    EXPECT_GT(q.weights[p], 0.0);
    wsum += q.weights[p];
    double s = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (i >= dim) {
        EXPECT_EQ(q.points[p][i], 0.0);
        continue;
      }
      EXPECT_GT(simplex ? q.points[p][i] : 1.0 - std::fabs(q.points[p][i]), 0.0);
      s += q.points[p][i];
    }
    EXPECT_LT(simplex ? s : 0.0, 1.0);
  }
  EXPECT_NEAR(wsum, measure, kTol * measure);
  const int d = q.degree, jmax = dim >= 2 ? d : 0, kmax = dim == 3 ? d : 0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; j <= jmax; ++j)
      for (int k = 0; k <= kmax; ++k) {
        if (simplex && i + j + k > d) continue;
        const double exact =
            simplex ? monomialSimplex(dim, i, j, k)
                    : monomialBox(i) * (dim >= 2 ? monomialBox(j) : 1.0) * (dim == 3 ? monomialBox(k) : 1.0);
        EXPECT_NEAR(integrate(q, i, j, k), exact, 1e-14) << i << " " << j << " " << k;
      }
}

}  // namespace

TEST(SolidShapeFunctions, TopologyTable) {
  const std::vector<std::string> names = solidTopologies();
  EXPECT_EQ(names, (std::vector<std::string>{"TET4", "TET10", "HEX8", "HEX20", "TRI3", "TRI6",
                                             "QUAD4", "QUAD8"}));
  const std::map<std::string, std::pair<int, int>> sizes = {
      {"TET4", {4, 3}}, {"TET10", {10, 3}}, {"HEX8", {8, 3}},  {"HEX20", {20, 3}},
      {"TRI3", {3, 2}}, {"TRI6", {6, 2}},   {"QUAD4", {4, 2}}, {"QUAD8", {8, 2}}};
  for (const std::string& n : names) {
    const SolidShape t = solidTopology(n);
    EXPECT_EQ(topologyName(t), n);
    EXPECT_EQ(nodeCount(t), sizes.at(n).first) << n;
    EXPECT_EQ(parametricDimension(t), sizes.at(n).second) << n;
    EXPECT_EQ(isQuadratic(t), n == "TET10" || n == "HEX20" || n == "TRI6" || n == "QUAD8");
  }
}

TEST(SolidShapeFunctions, ExodusAliasesCaseInsensitive) {
  const std::map<std::string, std::string> aliases = {
      {"tetra", "TET4"},  {"TETRA4", "TET4"}, {"Tet4", "TET4"},     {"tetra10", "TET10"},
      {"TET10", "TET10"}, {"hex", "HEX8"},    {"HEX8", "HEX8"},     {"hex20", "HEX20"},
      {"tri", "TRI3"},    {"TRI3", "TRI3"},   {"Triangle", "TRI3"}, {"tri6", "TRI6"},
      {"quad", "QUAD4"},  {"QUAD4", "QUAD4"}, {"quad8", "QUAD8"}};
  for (const auto& [alias, name] : aliases) EXPECT_EQ(topologyName(solidTopology(alias)), name);
  for (const char* bad : {"SHELL4", "shell", "BEAM2", "BAR2", "HEX27", "TET", ""}) {
    SolidShape t;
    EXPECT_FALSE(findSolidTopology(bad, t)) << bad;
    EXPECT_THROW(solidTopology(bad), std::invalid_argument) << bad;
  }
  try {
    solidTopology("SHELL4");
    FAIL() << "SHELL4 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("SHELL4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("QUAD8"), std::string::npos) << e.what();
  }
}

TEST(SolidShapeFunctions, NodesFollowExodusOrderAndKroneckerProperty) {
  for (const auto& [name, layout] : exodusLayouts()) {
    SCOPED_TRACE(name);
    const SolidShape t = solidTopology(name);
    const std::vector<Point3> expected = expectedNodes(layout);
    const std::vector<Point3>& nodes = nodeNaturalCoordinates(t);
    ASSERT_EQ(nodes.size(), expected.size());
    for (size_t a = 0; a < nodes.size(); ++a)
      for (int i = 0; i < 3; ++i) EXPECT_EQ(nodes[a][i], expected[a][i]) << "node " << a + 1;
    std::vector<double> N;
    std::vector<Point3> dN;
    for (size_t b = 0; b < expected.size(); ++b) {
      shapeFunctions(t, expected[b], N, dN);
      ASSERT_EQ(N.size(), expected.size());
      for (size_t a = 0; a < N.size(); ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, kTol);
    }
  }
}

// Sum_a N_a p(xi_a) = p(xi) for p constant, linear and (quadratic topologies) a complete
// quadratic; the same for the derivatives.
TEST(SolidShapeFunctions, CompletenessOfValuesAndDerivatives) {
  for (const std::string& name : solidTopologies()) {
    SCOPED_TRACE(name);
    const SolidShape t = solidTopology(name);
    const int dim = parametricDimension(t);
    const std::vector<Point3>& nodes = nodeNaturalCoordinates(t);
    std::vector<double> N;
    std::vector<Point3> dN;
    for (const Point3& xi : samplePoints(t)) {
      shapeFunctions(t, xi, N, dN);
      for (int which = 0; which < (isQuadratic(t) ? 3 : 2); ++which) {
        double v = 0.0;
        Point3 g = {0, 0, 0};
        for (size_t a = 0; a < N.size(); ++a) {
          const double pa = poly(which, nodes[a]);
          v += N[a] * pa;
          for (int i = 0; i < 3; ++i) g[i] += dN[a][i] * pa;
        }
        EXPECT_NEAR(v, poly(which, xi), kTol) << which;
        for (int i = 0; i < dim; ++i) {  // derivative of p by central differences (exact)
          Point3 lo = xi, hi = xi;
          lo[i] -= 0.5;
          hi[i] += 0.5;
          EXPECT_NEAR(g[i], poly(which, hi) - poly(which, lo), kTol) << which << " d" << i;
        }
      }
      for (size_t a = 0; a < N.size() && dim == 2; ++a) EXPECT_EQ(dN[a][2], 0.0);
    }
  }
}

// Central differences are exact (to round-off) for functions at most quadratic in the
// differentiated variable, which every shape function here is.
TEST(SolidShapeFunctions, DerivativesMatchCentralDifferences) {
  const double h = 1e-3;
  for (const std::string& name : solidTopologies()) {
    SCOPED_TRACE(name);
    const SolidShape t = solidTopology(name);
    std::vector<double> N, Nlo, Nhi;
    std::vector<Point3> dN, unused;
    for (const Point3& xi : samplePoints(t)) {
      shapeFunctions(t, xi, N, dN);
      for (int i = 0; i < parametricDimension(t); ++i) {
        Point3 lo = xi, hi = xi;
        lo[i] -= h;
        hi[i] += h;
        shapeFunctions(t, lo, Nlo, unused);
        shapeFunctions(t, hi, Nhi, unused);
        for (size_t a = 0; a < N.size(); ++a)
          EXPECT_NEAR(dN[a][i], (Nhi[a] - Nlo[a]) / (2 * h), 1e-10) << "N" << a + 1 << " d" << i;
      }
    }
  }
}

TEST(SolidQuadrature, RulesArePositiveInsideAndExactToTheirDegree) {
  for (int dim = 1; dim <= 3; ++dim)
    for (int n = 1; n <= 3; ++n) {
      SCOPED_TRACE("Gauss " + std::to_string(dim) + "D n=" + std::to_string(n));
      const QuadratureRule& q = gaussBoxRule(dim, n);
      EXPECT_EQ(q.size(), static_cast<int>(std::pow(n, dim)));
      EXPECT_EQ(q.degree, 2 * n - 1);
      checkRule(q, dim, false);
    }
  const std::map<int, int> triangle = {{1, 1}, {3, 2}, {7, 5}}, tet = {{1, 1}, {4, 2}, {14, 5}};
  for (const auto& [points, degree] : triangle) {
    SCOPED_TRACE("triangle " + std::to_string(points));
    EXPECT_EQ(triangleRule(points).size(), points);
    EXPECT_EQ(triangleRule(points).degree, degree);
    checkRule(triangleRule(points), 2, true);
  }
  for (const auto& [points, degree] : tet) {
    SCOPED_TRACE("tetrahedron " + std::to_string(points));
    EXPECT_EQ(tetrahedronRule(points).size(), points);
    EXPECT_EQ(tetrahedronRule(points).degree, degree);
    checkRule(tetrahedronRule(points), 3, true);
  }
  EXPECT_THROW(gaussBoxRule(3, 4), std::invalid_argument);
  EXPECT_THROW(triangleRule(6), std::invalid_argument);
  EXPECT_THROW(tetrahedronRule(11), std::invalid_argument);
}

// The mass rule integrates N_a N_b (times r when axisymmetric) exactly on affine elements:
// degree 2p in 3D and 2p + 1 in 2D (p = 1 linear, 2 quadratic); the stiffness rule integrates
// B^T D B (degree 2p - 2) exactly in 3D and plane strain.
TEST(SolidQuadrature, DegreesPerTopology) {
  for (const std::string& name : solidTopologies()) {
    SCOPED_TRACE(name);
    const SolidShape t = solidTopology(name);
    const int p = isQuadratic(t) ? 2 : 1, dim = parametricDimension(t);
    EXPECT_GE(massRule(t).degree, dim == 3 ? 2 * p : 2 * p + 1);
    const Kinematics k = dim == 3 ? Kinematics::ThreeD : Kinematics::PlaneStrain;
    EXPECT_GE(stiffnessRule(t, k).degree, 2 * p - 2);
  }
  EXPECT_EQ(stiffnessRule(SolidShape::Tet4, Kinematics::ThreeD).size(), 1);
  EXPECT_EQ(stiffnessRule(SolidShape::Tet10, Kinematics::ThreeD).size(), 4);
  EXPECT_EQ(stiffnessRule(SolidShape::Hex20, Kinematics::ThreeD).size(), 27);
  EXPECT_EQ(stiffnessRule(SolidShape::Tri3, Kinematics::PlaneStrain).size(), 1);
  EXPECT_EQ(stiffnessRule(SolidShape::Tri6, Kinematics::PlaneStrain).size(), 3);
  EXPECT_EQ(stiffnessRule(SolidShape::Tri3, Kinematics::Axisymmetric).size(), 7);
  EXPECT_EQ(massRule(SolidShape::Tet10).size(), 14);
}
