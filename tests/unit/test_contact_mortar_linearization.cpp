// The mortar integrals' derivatives by automatic differentiation (MortarLinearization.hpp)
// against central differences of the same integrals computed in double (MortarSegments.hpp),
// per face pair: d(int Phi_a) and d(int Phi_a nu . (x_s - x_m)) by every coordinate of both
// faces, for the slave and master kinds mortar takes (QUAD4 and TRI3 slaves on QUAD4, QUAD8
// and TRI6 masters, LINE2 edges on LINE2 and LINE3, plain and as rings), tilted and curved so
// that the clipping, the projections and the dual basis all move. And the normals' derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "contact/MortarLinearization.hpp"
#include "contact/MortarSegments.hpp"
#include "fd_tangent.hpp"

namespace choc {
namespace {

Face faceOf(SolidShape shape, std::vector<Point3> x, int firstNode, int edgeNodes = 0) {
  Face f;
  for (size_t a = 0; a < x.size(); ++a) f.nodes.push_back(firstNode + int(a));
  f.x = std::move(x);
  f.shape = shape;
  f.edgeNodes = edgeNodes;
  return f;
}

// x: both faces' coordinates (slave first); the integrals, D_a then G_a per slave node.
std::vector<double> integrals(const Face& s0, const Face& m0, const Point3& nu, bool axi, const std::vector<double>& x) {
  Face s = s0, m = m0;
  for (size_t k = 0; k < 3 * s.x.size(); ++k) s.x[k / 3][k % 3] = x[k];
  for (size_t k = 0; k < 3 * m.x.size(); ++k) m.x[k / 3][k % 3] = x[3 * s.x.size() + k];
  const DenseMatrix A = dualBasis(s, axi);
  std::vector<double> out(2 * s.nodes.size(), 0.0);
  for (const MortarPoint& p : mortarPoints(s, m, axi)) {
    const std::vector<double> phi = dualShapes(A, p.Ns);
    for (size_t a = 0; a < s.nodes.size(); ++a) {
      out[a] += phi[a] * p.weight;
      out[s.nodes.size() + a] += phi[a] * p.weight * dot(nu, p.xs - p.xm);
    }
  }
  return out;
}

void expectDerivatives(const Face& s, const Face& m, bool axi, const std::string& what) {
  const Point3 n = nodeNormal(s, 0), nu{-n[0], -n[1], -n[2]};
  std::vector<double> x;
  for (const Face* f : {&s, &m})
    for (const Point3& p : f->x) x.insert(x.end(), p.begin(), p.end());
  const OverlapDerivatives d = overlapDerivatives(s, m, std::vector<Point3>(s.nodes.size(), nu), axi);
  ASSERT_EQ(d.dD.size(), s.nodes.size()) << what << ": no overlap";
  const size_t ns = s.nodes.size();
  test::Dense J(int(2 * ns), int(x.size()));
  for (size_t a = 0; a < ns; ++a)
    for (int which = 0; which < 2; ++which)
      for (const auto& [node, g] : (which ? d.dG : d.dD)[a])
        for (int c = 0; c < 3; ++c) J(int(which * ns + a), 3 * node + c) = g[c];  // nodes 0.. in x's order
  test::TangentCheckOptions opt;
  opt.scale = 1e-2;  // of the faces' unit size: steps of 6e-8, far from every kink of the clipping
  opt.residualScale = 1.0;
  test::TangentCheck c;
  const auto R = [&](const std::vector<double>& y) { return integrals(s, m, nu, axi, y); };
  EXPECT_TRUE(tangentMatches(R, J, x, opt, &c)) << what;
  std::cout << "  [" << what << "] " << c.message() << "\n";
  EXPECT_TRUE(tangentMismatches(R, test::perturbed(J), x, opt)) << what;
}

TEST(ContactMortarLinearization, OverlapDerivativesAreTheIntegralsDerivatives) {
  // Slave faces outward +z about z = 0, warped off their plane; masters above, outward -z.
  const Face q4 = faceOf(SolidShape::Quad4, {{0, 0, 0}, {1, 0.1, 0.02}, {1.1, 1, -0.01}, {-0.1, 0.9, 0.03}}, 0);
  const Face t3 = faceOf(SolidShape::Tri3, {{0, 0, 0}, {1.2, 0.1, 0.05}, {0.2, 1.1, -0.04}}, 0);
  const Face mq4 = faceOf(SolidShape::Quad4, {{0.4, 0.3, 0.1}, {0.5, 1.4, 0.13}, {1.6, 1.3, 0.12}, {1.5, 0.2, 0.08}}, 4);
  // QUAD8 and TRI6 masters with their mid-edge nodes lifted: curved.
  const Face mq8 = faceOf(SolidShape::Quad8,
                          {{0.3, 0.2, 0.1}, {0.35, 1.3, 0.1}, {1.4, 1.35, 0.1}, {1.45, 0.25, 0.1}, {0.32, 0.75, 0.13},
                           {0.9, 1.32, 0.12}, {1.43, 0.8, 0.14}, {0.88, 0.22, 0.11}},
                          4);
  const Face mt6 = faceOf(SolidShape::Tri6,
                          {{0.5, -0.3, 0.1}, {-0.4, 1.2, 0.1}, {1.4, 1.0, 0.1}, {0.05, 0.45, 0.12}, {0.5, 1.1, 0.13},
                           {0.95, 0.35, 0.11}},
                          3);
  expectDerivatives(q4, mq4, false, "QUAD4 on QUAD4");
  expectDerivatives(q4, mq8, false, "QUAD4 on QUAD8");
  expectDerivatives(faceOf(SolidShape::Tri3, t3.x, 0), mt6, false, "TRI3 on TRI6");
  // Edges in the x-y plane (r = x): the slave outward +y, masters above, outward -y.
  const Face e2 = faceOf(SolidShape::Quad4, {{1.0, 0, 0}, {0.2, 0.05, 0}}, 0, 2);
  const Face me2 = faceOf(SolidShape::Quad4, {{0.4, 0.1, 0}, {1.5, 0.07, 0}}, 2, 2);
  const Face me3 = faceOf(SolidShape::Quad4, {{0.4, 0.1, 0}, {1.5, 0.07, 0}, {0.9, 0.11, 0}}, 2, 3);
  expectDerivatives(e2, me2, false, "LINE2 on LINE2");
  expectDerivatives(e2, me2, true, "LINE2 on LINE2, rings");
  expectDerivatives(e2, me3, true, "LINE2 on LINE3, rings");
}

TEST(ContactMortarLinearization, NormalDerivative) {
  const Face q4 = faceOf(SolidShape::Quad4, {{0, 0, 0}, {1, 0.1, 0.02}, {1.1, 1, -0.01}, {-0.1, 0.9, 0.03}}, 0);
  const Point3 w{0.3, -0.7, 0.2};
  for (int a = 0; a < 4; ++a) {
    NodeGradient g;
    addNormalDerivative(q4, a, w, g);
    test::Dense J(1, 12);
    for (const auto& [node, v] : g)
      for (int c = 0; c < 3; ++c) J(0, 3 * node + c) = v[c];
    std::vector<double> x;
    for (const Point3& p : q4.x) x.insert(x.end(), p.begin(), p.end());
    const auto R = [&](const std::vector<double>& y) {
      Face f = q4;
      for (size_t k = 0; k < 12; ++k) f.x[k / 3][k % 3] = y[k];
      return std::vector<double>{dot(w, nodeNormal(f, a))};
    };
    test::TangentCheckOptions opt;
    opt.scale = 1e-2;
    opt.residualScale = 1.0;
    EXPECT_TRUE(tangentMatches(R, J, x, opt)) << a;
    EXPECT_TRUE(tangentMismatches(R, test::perturbed(J), x, opt)) << a;
  }
}

}  // namespace
}  // namespace choc
