// Loads of the direct transient: the consistent nodal forces of a uniform pressure (known
// fractions of p A per node, the whole-ring area of axisymmetric edges), the ramp, and the
// loads' work (exact for constant loads and for a ramp against a linear motion).
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "physics/Loads.hpp"

namespace choc {
namespace {

Face edge(std::vector<Point3> x) {
  Face f;
  f.x = std::move(x);
  for (size_t a = 0; a < f.x.size(); ++a) f.nodes.push_back(int(a));
  f.edgeNodes = int(f.x.size());
  return f;
}

// The lower edge of a counter-clockwise element, from x = 1 to 3 (outward normal -y): the
// pressure pushes it along +y, half of p L on each LINE2 node; on LINE3 (mid node third)
// 1/6, 1/6 and 2/3 of p L.
TEST(PressureForces, LineEdgesShareTheLoadByTheirShapeFunctions) {
  const double p = 7e4;
  auto f2 = pressureForces({edge({{1, 0, 0}, {3, 0, 0}})}, p, false);
  ASSERT_EQ(f2.size(), 2u);
  for (int a : {0, 1}) {
    EXPECT_NEAR(f2[a][1], p, 1e-9 * p);
    EXPECT_EQ(f2[a][0], 0.0);
    EXPECT_EQ(f2[a][2], 0.0);
  }
  auto f3 = pressureForces({edge({{1, 0, 0}, {3, 0, 0}, {2, 0, 0}})}, p, false);
  EXPECT_NEAR(f3[0][1], 2 * p / 6, 1e-9 * p);
  EXPECT_NEAR(f3[1][1], 2 * p / 6, 1e-9 * p);
  EXPECT_NEAR(f3[2][1], 2 * p * 4 / 6, 1e-9 * p);
}

// Axisymmetric: the edge from r = 1 to 3 is an annulus of area pi (3^2 - 1^2) = 8 pi; the
// linear edge's nodes get 2 pi p integral of N_a r dr: (2 pi p) (L / 6) (2 r_a + r_b).
TEST(PressureForces, AxisymmetricEdgesCarryTheWholeRing) {
  const double p = 1.0;
  auto f = pressureForces({edge({{1, 0, 0}, {3, 0, 0}})}, p, true);
  EXPECT_NEAR(f[0][1] + f[1][1], 8 * M_PI * p, 1e-12);
  EXPECT_NEAR(f[0][1], 2 * M_PI * p * (2.0 / 6.0) * (2 * 1 + 3), 1e-12);
  EXPECT_NEAR(f[1][1], 2 * M_PI * p * (2.0 / 6.0) * (2 * 3 + 1), 1e-12);
}

// A tilted flat QUAD4 face (2 x 3, normal n): each corner gets p A / 4 against n; a TRI6 face
// gives its corners nothing and each mid-side node p A / 3.
TEST(PressureForces, FacesPushAgainstTheirOutwardNormal) {
  const double c = std::cos(0.4), s = std::sin(0.4), p = 2.5;
  // The rectangle [0, 2] x [0, 3] turned about x: tangents (1, 0, 0) and (0, c, s).
  Face q;
  q.shape = SolidShape::Quad4;
  q.nodes = {0, 1, 2, 3};
  q.x = {{0, 0, 0}, {2, 0, 0}, {2, 3 * c, 3 * s}, {0, 3 * c, 3 * s}};
  const Point3 n{0, -s, c};  // (1, 0, 0) x (0, c, s): counter-clockwise seen from n
  auto f = pressureForces({q}, p, false);
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[a][k], -p * 6.0 / 4.0 * n[k], 1e-12) << a << " " << k;
  Face t;
  t.shape = SolidShape::Tri6;
  t.nodes = {0, 1, 2, 3, 4, 5};
  t.x = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  auto g = pressureForces({t}, p, false);  // area 2, normal +z
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(g[a][2], 0.0, 1e-12);
  for (int a = 3; a < 6; ++a) EXPECT_NEAR(g[a][2], -p * 2.0 / 3.0, 1e-12);
}

TEST(LoadGroup, RampGrowsLinearlyThenHolds) {
  LoadGroup g;
  g.rampTime = 0.07;
  EXPECT_EQ(g.factor(0.0), 0.0);
  EXPECT_NEAR(g.factor(0.035), 0.5, 1e-15);
  EXPECT_EQ(g.factor(0.07), 1.0);
  EXPECT_EQ(g.factor(3.0), 1.0);
  g.rampTime = 0.0;
  EXPECT_EQ(g.factor(0.0), 1.0);
}

// Work of a constant force F and of a ramped one (T = 4 dt) while u = w t: F.w t and, past the
// ramp, F.w (t - T / 2); the trapezoidal rule is exact for both. The state survives a restore.
TEST(LoadWork, ExactForConstantAndRampedLoadsOnALinearMotion) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(3, 0, comm));
  auto F = rcp(new Vector(map));
  F->putScalar(2.0);  // F.w = 3 x 2 x 0.5 (w = 0.5 in each component)
  Vector u(map);
  Loads constant, ramped;
  constant.add({"c", F, 0.0});
  ramped.add({"r", F, 0.4});
  LoadWork wc(&constant), wr(&ramped), copy(&ramped);
  const double dt = 0.1, fw = 3.0;
  for (int n = 0; n <= 10; ++n) {
    const double t = n * dt;
    u.putScalar(0.5 * t);
    const double c = wc.update(u, t), r = wr.update(u, t);
    EXPECT_NEAR(c, fw * t, 1e-12);
    if (t >= 0.4 - 1e-12) EXPECT_NEAR(r, fw * (t - 0.2), 1e-12) << "t = " << t;
    if (n == 5) copy.restore(wr.state());
  }
  u.putScalar(0.5 * 1.1);
  EXPECT_NEAR(copy.update(u, 1.1), fw * (1.1 - 0.2), 1e-12);  // resumed after step 5
  EXPECT_NEAR(wr.update(u, 1.1), fw * (1.1 - 0.2), 1e-12);
}

// Groups with the same ramp share one vector (summed in the order given); others stay apart.
TEST(Loads, GroupsWithOneRampAreSummed) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(2, 0, comm));
  auto a = rcp(new Vector(map)), b = rcp(new Vector(map)), c = rcp(new Vector(map));
  a->putScalar(1.0);
  b->putScalar(2.0);
  c->putScalar(4.0);
  Loads loads;
  loads.add({"a", a, 0.1});
  loads.add({"b", b, 0.0});
  loads.add({"c", c, 0.1});
  ASSERT_EQ(loads.groups().size(), 2u);
  EXPECT_EQ(loads.groups()[0].name, "a, c");
  Vector out(map);
  loads.subtractFrom(0.05, out);  // -(0.5 x 5 + 2)
  for (double v : out.getData()) EXPECT_NEAR(v, -4.5, 1e-15);
}

}  // namespace
}  // namespace choc
