// The shock law on configurations solvable by hand: gaps and forces of every obstacle shape,
// the obstacle frames of the reference decks, the inner circle in two directions, grazing.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/ShockLaw.hpp"

namespace choc {
namespace {

ShockLawParameters law(ObstacleShape shape, Vec3 axis, double d1, double d2) {
  ShockLawParameters p;
  p.shape = shape;
  p.frame = obstacleFrame(axis);
  p.dist1 = d1;
  p.dist2 = d2;
  p.normalStiffness = 1e6;
  return p;
}

void expectVec(const Vec3& a, const Vec3& b, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

TEST(ObstacleFrame, ReferenceDeckFramesPutTheShockNormalOnTheBarAxis) {
  // Run 1 of SDNL111 A: axis z, BI_PLAN_Z: the planes' normal e3 must be the bar axis x.
  const auto fz = obstacleFrame({0, 0, 1});
  EXPECT_NEAR(std::abs(fz.e3[0]), 1.0, 1e-15);
  // Runs 2 and 3: axis y, BI_PLAN_Y: e2 along x; the circle's plane (orthogonal to y)
  // contains x.
  const auto fy = obstacleFrame({0, 1, 0});
  EXPECT_NEAR(std::abs(fy.e2[0]), 1.0, 1e-15);
  expectVec(fy.e1, {0, 1, 0}, 1e-15);
  // Any axis: a right-handed orthonormal frame with e1 = n.
  const auto f = obstacleFrame({1, 2, -2}, 0.3);
  expectVec(f.e1, {1.0 / 3, 2.0 / 3, -2.0 / 3}, 1e-15);
  EXPECT_NEAR(dot(f.e1, f.e2), 0, 1e-15);
  EXPECT_NEAR(dot(f.e2, f.e3), 0, 1e-15);
  EXPECT_NEAR(dot(f.e2, f.e2), 1, 1e-15);
  const Vec3 cross{f.e1[1] * f.e2[2] - f.e1[2] * f.e2[1], f.e1[2] * f.e2[0] - f.e1[0] * f.e2[2],
                   f.e1[0] * f.e2[1] - f.e1[1] * f.e2[0]};
  expectVec(cross, f.e3, 1e-15);
  EXPECT_THROW(obstacleFrame({0, 0, 0}), std::invalid_argument);
}

TEST(ShockLaw, TwoPlanesRepelAlongTheNormalOnEitherSide) {
  const auto p = law(ObstacleShape::BiPlanZ, {0, 0, 1}, 0.5e-5, 0.5e-5);
  ShockLawState st;
  // |d.x| = 0.8e-5 < DIST_1 + DIST_2 = 1e-5: 2e-6 of penetration.
  for (double side : {-1.0, 1.0}) {
    const Vec3 d{side * 0.8e-5, 3e-3, 0};  // lateral offsets do not matter for planes
    auto r = evaluateShock(p, d, {0, 0, 0}, 0, st, false);
    EXPECT_NEAR(r.gap, -2e-6, 1e-18);
    EXPECT_TRUE(r.closed);
    EXPECT_NEAR(r.normalForce, 2.0, 1e-9);                 // K * 2e-6
    expectVec(r.forceOnNode2, {side * 2.0, 0, 0}, 1e-9);   // pushes node 2 away from node 1
  }
  // Open: no force.
  auto r = evaluateShock(p, {1.1e-5, 0, 0}, {-1, 0, 0}, 0, st, false);  // gap +1e-6
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.normalForce, 0.0);
}

TEST(ShockLaw, DampingNeverMakesTheForceTensile) {
  auto p = law(ObstacleShape::BiPlanY, {0, 1, 0}, 0, 1e-5);
  p.normalDamping = 2e4;
  ShockLawState st;
  // Slight penetration (K delta = 1 N) but separating fast: -K delta - C rate < 0 -> 0.
  auto r = evaluateShock(p, {-1e-5 + 1e-6, 0, 0}, {-1, 0, 0}, 0, st, false);
  ASSERT_TRUE(r.closed);
  // d.e2 with e2 = -x: s = 9e-6 > 0, m = -x, gap rate = w.m = +1 (opening).
  EXPECT_EQ(r.normalForce, 0.0);
  // Closing: the dashpot adds to the spring.
  r = evaluateShock(p, {-1e-5 + 1e-6, 0, 0}, {+0.1, 0, 0}, 0, st, false);
  EXPECT_NEAR(r.normalForce, 1e6 * 1e-6 + 2e4 * 0.1, 1e-9);
}

TEST(ShockLaw, CircleUsesTheDistanceInThePlaneOrthogonalToTheAxis) {
  const auto p = law(ObstacleShape::BiCercle, {0, 1, 0}, 1e-5, 1e-5);
  ShockLawState st;
  // r = |(3e-6, *, 4e-6)| = 5e-6 (the y component lies along the axis and is ignored; its
  // removal costs round-off of order |y| eps).
  auto r = evaluateShock(p, {3e-6, 1e-3, 4e-6}, {0, 0, 0}, 0, st, false);
  EXPECT_NEAR(r.gap, 5e-6 - 2e-5, 1e-3 * 1e-15);
  EXPECT_NEAR(r.normalForce, 1e6 * 1.5e-5, 1e-9);
  expectVec(r.forceOnNode2, {0.6 * 15, 0, 0.8 * 15}, 1e-9);  // radial, outward
}

TEST(ShockLaw, InnerCircleHasFreePlayThenPullsBackInEveryDirection) {
  const auto p = law(ObstacleShape::BiCercInt, {0, 1, 0}, 1e-6, 2e-6);
  ShockLawState st;
  // Inside the free play (r < DIST_2 - DIST_1 = 1e-6): no force, in both directions.
  for (Vec3 d : {Vec3{0.9e-6, 0, 0}, Vec3{0, 0, -0.9e-6}, Vec3{-0.5e-6, 0, 0.5e-6}}) {
    auto r = evaluateShock(p, d, {0, 0, 0}, 0, st, false);
    EXPECT_FALSE(r.closed);
    EXPECT_EQ(r.normalForce, 0.0);
  }
  // Beyond it, along x and along z: pulled back towards node 1 with K (r - 1e-6).
  auto rx = evaluateShock(p, {3e-6, 0, 0}, {0, 0, 0}, 0, st, false);
  EXPECT_NEAR(rx.gap, -2e-6, 1e-18);
  expectVec(rx.forceOnNode2, {-2.0, 0, 0}, 1e-9);
  auto rz = evaluateShock(p, {0, 0, -3e-6}, {0, 0, 0}, 0, st, false);
  expectVec(rz.forceOnNode2, {0, 0, 2.0}, 1e-9);
  auto rneg = evaluateShock(p, {-3e-6, 0, 0}, {0, 0, 0}, 0, st, false);
  expectVec(rneg.forceOnNode2, {2.0, 0, 0}, 1e-9);
}

TEST(ShockLaw, GrazingAtZeroGapWithTangentialMotionGivesNoForce) {
  auto p = law(ObstacleShape::BiPlanZ, {0, 0, 1}, 0, 1e-5);
  p.normalDamping = 1e4;
  ShockLawState st;
  // Exactly touching (gap 0) and sliding along the plane: no normal force.
  auto r = evaluateShock(p, {-1e-5, 0, 0}, {0, 2.0, 0}, 1e-6, st, true);
  EXPECT_EQ(r.gap, 0.0);
  EXPECT_EQ(r.normalForce, 0.0);
  expectVec(r.forceOnNode2, {0, 0, 0}, 0.0);
}

TEST(ShockLaw, ParsesShapeNames) {
  for (const auto& n : obstacleShapeNames()) EXPECT_NO_THROW(parseObstacleShape(n));
  EXPECT_THROW(parseObstacleShape("BI_PLAN_X"), std::invalid_argument);
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// A plane (PLAN_Z, outward normal +z) pressing with 10 N; friction in the plane x-y.
ShockLawParameters frictionLaw(FrictionLaw kind) {
  ShockLawParameters p;
  p.shape = ObstacleShape::PlanZ;
  p.frame = obstacleFrame({1, 0, 0});
  p.dist1 = 0.5;
  p.normalStiffness = 20;
  p.tangentialStiffness = 4e5;
  p.friction = 0.1;
  p.frictionLaw = kind;
  return p;
}

// One node against the fixed plane: d = -u, w = -v (node 2 is the obstacle).
ShockResponse step(const ShockLawParameters& p, ShockLawState& st, const Vec3& u, const Vec3& v,
                   double dt) {
  return evaluateShock(p, {-u[0], -u[1], -u[2]}, {-v[0], -v[1], -v[2]}, dt, st, true);
}

TEST(ShockLawFriction, VelocityReversalSlidesAlongTheVelocityAndSticksWhenItReverses) {
  const auto p = frictionLaw(FrictionLaw::VelocityReversal);
  ShockLawState st;
  // At rest on closing: sticks, no force.
  auto r = step(p, st, {0, 0, 0}, {0, 0, 0}, 1e-3);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.normalForce, 10.0, 1e-12);
  EXPECT_NEAR(r.tangentialForce, 0.0, 1e-15);
  // Moving 1e-6 m along +x: the stick spring holds 0.4 N (< mu N = 1 N) on node 1 against it.
  r = step(p, st, {1e-6, 0, 0}, {1e-3, 0, 0}, 1e-3);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.tangentialForceVector[0], 0.4, 1e-9);  // on node 2 (the plane): along +x
  // 1e-5 m: the spring would hold 4 N > 1 N: it slides, mu N along the (node's) velocity.
  r = step(p, st, {1e-5, 0, 0}, {0.3, 0.4, 0}, 1e-3);
  EXPECT_TRUE(r.sliding);
  expectVec(r.tangentialForceVector, {0.6, 0.8, 0}, 1e-12);  // node 1 gets -mu N v / |v|
  EXPECT_NEAR(r.slipSpeed, 0.5, 1e-15);
  // Still moving the same way (any distance): slides on, along the velocity.
  r = step(p, st, {2e-3, 0, 0}, {1, 0, 0}, 1e-3);
  EXPECT_TRUE(r.sliding);
  expectVec(r.tangentialForceVector, {1, 0, 0}, 1e-12);
  // The velocity reverses: it sticks from the last slip force (+1 N on the plane) less the
  // stick spring over the way back (1e-6 m: 0.4 N): 0.6 N.
  r = step(p, st, {2e-3 - 1e-6, 0, 0}, {-1e-3, 0, 0}, 1e-3);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.tangentialForceVector[0], 0.6, 1e-9);
  // 6e-6 m back: 1 - 2.4 = -1.4 N, beyond mu N: it slides back, against the new velocity.
  r = step(p, st, {2e-3 - 6e-6, 0, 0}, {-1e-3, 0, 0}, 1e-3);
  EXPECT_TRUE(r.sliding);
  expectVec(r.tangentialForceVector, {-1, 0, 0}, 1e-12);
  // Opening forgets everything.
  r = step(p, st, {0, 0, 1.0}, {0, 0, 0}, 1e-3);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.tangentialForce, 0.0);
}

TEST(ShockLawFriction, ElasticPlasticSpringIsReturnedOntoTheCone) {
  const auto p = frictionLaw(FrictionLaw::ElasticPlastic);
  ShockLawState st;
  step(p, st, {0, 0, 0}, {0, 0, 0}, 1e-3);
  // 1e-3 s at 1e-3 m/s along +x: the spring stretches 1e-6 m, 0.4 N.
  auto r = step(p, st, {1e-6, 0, 0}, {1e-3, 0, 0}, 1e-3);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.tangentialForceVector[0], 0.4, 1e-9);
  EXPECT_NEAR(r.tangentialEnergy, 0.4 * 0.4 / (2 * 4e5), 1e-15);
  // A further 1e-5 m: 4.4 N on trial, returned to mu N = 1 N; the spring keeps 2.5e-6 m.
  r = step(p, st, {1.1e-5, 0, 0}, {1e-2, 0, 0}, 1e-3);
  EXPECT_TRUE(r.sliding);
  EXPECT_NEAR(r.tangentialForceVector[0], 1.0, 1e-12);
  // Back by 1e-6 m: the spring unloads elastically, 1 - 0.4 = 0.6 N, no slip.
  r = step(p, st, {1e-5, 0, 0}, {-1e-3, 0, 0}, 1e-3);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.tangentialForceVector[0], 0.6, 1e-9);
}

}  // namespace
}  // namespace choc
