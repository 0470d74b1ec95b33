// Mortar contact with dual multipliers: the dual basis is biorthogonal and a
// partition of unity, the overlaps' integration points measure the overlap's area, and the
// pairing's weights reproduce linear fields (which is what passes the patch test).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "contact/ContactPairing.hpp"
#include "contact/MortarSegments.hpp"
#include "fem/Quadrature.hpp"
#include "test_contact_helpers.hpp"
#include "test_mesh_helpers.hpp"

namespace choc {
namespace {

Face quad(std::vector<Point3> x) {
  Face f;
  f.nodes = {0, 1, 2, 3};
  f.x = std::move(x);
  f.shape = SolidShape::Quad4;
  return f;
}

Face tri(std::vector<Point3> x) {
  Face f;
  f.nodes = {0, 1, 2};
  f.x = std::move(x);
  f.shape = SolidShape::Tri3;
  return f;
}

Face edge(Point3 a, Point3 b) {
  Face f;
  f.nodes = {0, 1};
  f.x = {a, b};
  f.edgeNodes = 2;
  return f;
}

// int Phi_a N_b over the face, by a rule exact for the integrands (A constant, N_a N_b J).
void expectBiorthogonal(const Face& f, bool axi) {
  const DenseMatrix A = dualBasis(f, axi);
  const int n = static_cast<int>(f.nodes.size());
  const QuadratureRule& r = f.edgeNodes ? gaussBoxRule(1, 3) : isTriangle(f) ? triangleRule(7) : gaussBoxRule(2, 3);
  std::vector<double> PN(n * n, 0.0), I(n, 0.0);
  double scale = 0;
  for (int k = 0; k < r.size(); ++k) {
    const FacePoint q = evaluateFace(f, r.points[k][0], r.points[k][1]);
    const double J = norm(cross(q.dxi, q.deta)) * r.weights[k] * (axi ? 2 * M_PI * q.x[0] : 1.0);
    const std::vector<double> phi = dualShapes(A, q.N);
    double sum = 0;
    for (int a = 0; a < n; ++a) {
      sum += phi[a];
      I[a] += q.N[a] * J;
      for (int b = 0; b < n; ++b) PN[a * n + b] += phi[a] * q.N[b] * J;
    }
    EXPECT_NEAR(sum, 1.0, 1e-13);  // partition of unity
    scale += J;
  }
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) EXPECT_NEAR(PN[a * n + b], a == b ? I[a] : 0.0, 1e-13 * scale) << a << b;
}

TEST(ContactMortar, DualBasisIsBiorthogonal) {
  // A planar trapezoid (not a parallelogram), a triangle, a LINE2 edge plain and as a ring.
  expectBiorthogonal(quad({{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.2, 1.3, 0}}), false);
  expectBiorthogonal(tri({{0, 0, 1}, {1, 0.2, 1}, {0.3, 0.9, 1.1}}), false);
  expectBiorthogonal(edge({0.5, 0, 0}, {1.5, 0.3, 0}), false);
  expectBiorthogonal(edge({0.5, 0, 0}, {1.5, 0.3, 0}), true);
  Face q8 = quad({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  q8.shape = SolidShape::Quad8;
  EXPECT_FALSE(mortarSlaveFace(q8));
  EXPECT_THROW(dualBasis(q8, false), std::invalid_argument);
}

double totalWeight(const std::vector<MortarPoint>& pts) {
  double w = 0;
  for (const auto& p : pts) w += p.weight;
  return w;
}

TEST(ContactMortar, OverlapPointsMeasureTheOverlap) {
  // Slave: the unit square at z = 0, outward +z (counter-clockwise seen from +z).
  const Face s = quad({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  // Master: a square shifted by (0.5, 0.25), 1e-3 above, outward -z (clockwise from +z).
  const Face m = quad({{0.5, 0.25, 1e-3}, {0.5, 1.25, 1e-3}, {1.5, 1.25, 1e-3}, {1.5, 0.25, 1e-3}});
  const std::vector<MortarPoint> pts = mortarPoints(s, m, false);
  EXPECT_NEAR(totalWeight(pts), 0.5 * 0.75, 1e-14);
  for (const auto& p : pts) {
    EXPECT_NEAR(p.xm[0] - p.xs[0], 0.0, 1e-14);  // projected along the normal
    EXPECT_NEAR(p.xm[1] - p.xs[1], 0.0, 1e-14);
    EXPECT_NEAR(p.xm[2] - p.xs[2], 1e-3, 1e-14);
    EXPECT_TRUE(p.xs[0] >= 0.5 - 1e-14 && p.xs[1] >= 0.25 - 1e-14);  // inside the overlap
  }
  // A triangle master (outward -z) cutting the square's corner: the overlap is the triangle
  // (0.5, 0)-(1, 0)-(1, 0.5) of area 1/8.
  const Face t = tri({{0.5, 0, -1e-3}, {1, 0.5, -1e-3}, {1.5, 0, -1e-3}});
  EXPECT_NEAR(totalWeight(mortarPoints(s, t, false)), 0.125, 1e-14);
  // A master facing the same way, or beside the slave, gives nothing.
  const Face same = quad({{0.5, 0.25, 1e-3}, {1.5, 0.25, 1e-3}, {1.5, 1.25, 1e-3}, {0.5, 1.25, 1e-3}});
  EXPECT_TRUE(mortarPoints(s, same, false).empty());
  const Face beside = quad({{1.5, 0, 0}, {1.5, 1, 0}, {2.5, 1, 0}, {2.5, 0, 0}});
  EXPECT_TRUE(mortarPoints(s, beside, false).empty());
  // Edges: the slave from r = 1 to 0 on the x axis (outward +y), the master from
  // r = 0.4 to 2 above it (outward -y): overlap of length 0.6, as a ring pi (1 - 0.16).
  const Face se = edge({1, 0, 0}, {0, 0, 0}), me = edge({0.4, 1e-3, 0}, {2, 1e-3, 0});
  EXPECT_NEAR(totalWeight(mortarPoints(se, me, false)), 0.6, 1e-14);
  EXPECT_NEAR(totalWeight(mortarPoints(se, me, true)), M_PI * (1 - 0.16), 1e-13);
}

// Every slave node: weights summing to 1, the gap, and sum_m w_m x_m = x_j laterally (the
// weights reproduce linear fields: the patch test's uniform strain passes exactly).
void expectLinearReproduction(const Mesh& m, const PairDefinition& def, size_t slaves) {
  const PairingResult r = pairMortar(m, def, 0);
  ASSERT_EQ(r.projections.size(), slaves);
  EXPECT_TRUE(r.unpaired.empty());
  for (const auto& p : r.projections) EXPECT_NEAR(std::abs(p.normal[2]), 1.0, 1e-14);
  const double area = test::expectProjectionsAbove(m, r, 2e-5, {1e-13, 1e-14, 1e-16});
  EXPECT_NEAR(area, 4e-4, 1e-17);
}

TEST(ContactMortar, WeightsReproduceLinearFields) {
  // Fine slave (3 x 3) on one master face, and a coarse slave (2 x 2) on a 3 x 3 master, whose
  // dual functions reach master nodes of several faces.
  const Mesh a = test::barContactScene(1, 3, 2e-5);
  expectLinearReproduction(a, {"ifc", "CNT_POU1", "CNT_POU2", 1e-3}, 16);
  const Mesh b = test::barContactScene(3, 2, 2e-5);
  expectLinearReproduction(b, {"ifc", "CNT_POU2", "CNT_POU1", 1e-3}, 16);
  expectLinearReproduction(b, {"ifc", "CNT_POU1", "CNT_POU2", 1e-3}, 9);
  // Faces whose edges coincide (2 x 2 on 4 x 4, and the reverse).
  const Mesh c = test::barContactScene(2, 4, 2e-5);
  expectLinearReproduction(c, {"ifc", "CNT_POU1", "CNT_POU2", 1e-3}, 25);
  expectLinearReproduction(c, {"ifc", "CNT_POU2", "CNT_POU1", 1e-3}, 9);
  // Beyond the search distance nothing overlaps.
  EXPECT_THROW(pairMortar(a, {"ifc", "CNT_POU1", "CNT_POU2", 1e-6}, 0), std::invalid_argument);
}

// Numbering independence (docs/verification/properties.md): the pairing does not depend on the
// mesh's numbering. The scene with its
// nodes renumbered at random gives, node for node, the same weights on the same master nodes,
// gaps and areas (the sums only change order: round-off).
TEST(ContactMortar, PairingDoesNotDependOnTheNumbering) {
  const Mesh m = test::barContactScene(3, 2, 2e-5);
  std::vector<int> perm;
  const Mesh r = renumberedMesh(m, 2026, &perm);
  const PairDefinition def{"ifc", "CNT_POU1", "CNT_POU2", 1e-3};
  const PairingResult a = pairMortar(m, def, 0), b = pairMortar(r, def, 0);
  ASSERT_EQ(a.projections.size(), b.projections.size());
  std::map<int, const SlaveProjection*> renumbered;
  for (const auto& p : b.projections) renumbered[p.slaveNode] = &p;
  for (const auto& p : a.projections) {
    ASSERT_TRUE(renumbered.count(perm[p.slaveNode]));
    const SlaveProjection& q = *renumbered[perm[p.slaveNode]];
    EXPECT_NEAR(q.gap0, p.gap0, 1e-18);
    EXPECT_NEAR(q.area, p.area, 1e-15 * p.area);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(q.normal[d], p.normal[d], 1e-15);
    ASSERT_EQ(q.masterNodes.size(), p.masterNodes.size());
    std::map<int, double> w;
    for (size_t i = 0; i < q.masterNodes.size(); ++i) w[q.masterNodes[i]] = q.weights[i];
    for (size_t i = 0; i < p.masterNodes.size(); ++i) {
      ASSERT_TRUE(w.count(perm[p.masterNodes[i]])) << "master node " << p.masterNodes[i];
      EXPECT_NEAR(w[perm[p.masterNodes[i]]], p.weights[i], 1e-14);
    }
  }
}

}  // namespace
}  // namespace choc
