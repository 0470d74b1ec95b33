// One rigid body in the velocity-Verlet step of central differences (src/rigid/RigidBody.hpp):
// its material points keep their distances, its centre follows the closed forms of free flight
// and of a constant force exactly (Verlet is exact for a constant acceleration), a couple turns
// it by its moment, its momenta are conserved in free flight, its state survives a checkpoint bit
// for bit.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rigid/RigidBody.hpp"

namespace choc {
namespace {

// Eight point masses at the corners of a 0.2 x 0.3 x 0.5 box turned and moved off the origin.
std::vector<Vec3> corners() {
  const Matrix33 Q = rotationFromVector({0.2, -0.7, 0.4});
  std::vector<Vec3> x;
  for (int i = 0; i < 8; ++i) {
    const Vec3 local = {0.2 * (i & 1), 0.3 * ((i >> 1) & 1), 0.5 * ((i >> 2) & 1)};
    const Vec3 t = Q * local;
    x.push_back({1.0 + t[0], -2.0 + t[1], 0.5 + t[2]});
  }
  return x;
}

RigidBody box() {
  const std::vector<Vec3> x = corners();
  MassPropertiesSum sum(x[0]);
  for (size_t i = 0; i < x.size(); ++i) sum.addPoint(x[i], 1.0 + 0.25 * double(i));  // unequal masses
  return RigidBody("box", sum.properties());
}

double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }

TEST(RigidBody, ItsPointsMoveRigidlyAndItsMomentaAreConservedInFreeFlight) {
  RigidBody b = box();
  const std::vector<Vec3> X = corners();
  b.setMotion({0.3, -1.0, 2.0}, {4.0, 1.0, -7.0});
  const Vec3 c0 = b.centre(), V = b.centreVelocity(), L0 = b.angularMomentum();
  const double E0 = b.kineticEnergy(), h = 1e-3;
  const int steps = 2000;
  double energyError = 0.0;
  for (int n = 0; n < steps; ++n) {
    b.kick({0, 0, 0}, {0, 0, 0}, h / 2);
    b.drift(h);
    b.kick({0, 0, 0}, {0, 0, 0}, h / 2);
    energyError = std::max(energyError, std::abs(b.kineticEnergy() - E0) / E0);
  }
  for (size_t i = 0; i < X.size(); ++i)
    for (size_t j = i + 1; j < X.size(); ++j)
      EXPECT_NEAR(distance(b.position(X[i]), b.position(X[j])), distance(X[i], X[j]), 1e-14);
  const double t = h * steps;
  // one rounding per step of a sum of size |c| ~ 5 m: steps eps |c|
  const double summed = steps * 2.2e-16 * 5.0;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.centre()[k], c0[k] + V[k] * t, summed);
  const Vec3 L = b.angularMomentum();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(L[k], L0[k], 1e-13 * norm(L0));
  // the splitting's energy error: O((h |w|)^2) = 6.6e-5 at h |w| = 8.1e-3; measured well below
  EXPECT_LT(energyError, std::pow(h * norm(Vec3{4.0, 1.0, -7.0}), 2));
  // a point's velocity is the centre's plus w x r, and its displacement x - X
  const Vec3 v0 = b.velocity(X[3]), w = b.angularVelocity();
  const Vec3 r = b.position(X[3]) - b.centre();
  const Vec3 expected = {V[0] + cross(w, r)[0], V[1] + cross(w, r)[1], V[2] + cross(w, r)[2]};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(v0[k], expected[k], 1e-14);
  EXPECT_NEAR(norm(b.displacement(X[3]) - (b.position(X[3]) - X[3])), 0.0, 1e-15);
}

TEST(RigidBody, AConstantForceMovesTheCentreOnItsParabolaExactly) {
  RigidBody b = box();
  const Vec3 F = {10.0, -4.0, 3.0}, c0 = b.centre();
  b.setMotion({1.0, 0.0, -0.5}, {0.0, 0.0, 0.0});
  const double h = 1e-3, m = b.mass();
  for (int n = 0; n < 500; ++n) {
    b.kick(F, {0, 0, 0}, h / 2);
    b.drift(h);
    b.kick(F, {0, 0, 0}, h / 2);
  }
  const double t = 0.5;
  const Vec3 v0 = {1.0, 0.0, -0.5};
  for (int k = 0; k < 3; ++k) {
    // exact but for one rounding per step and kick of sums of size ~ 3: 1,000 eps 3
    EXPECT_NEAR(b.centre()[k], c0[k] + v0[k] * t + 0.5 * F[k] / m * t * t, 1000 * 2.2e-16 * 3);
    EXPECT_NEAR(b.centreVelocity()[k], v0[k] + F[k] / m * t, 1000 * 2.2e-16 * 3);
  }
  EXPECT_NEAR(norm(b.rotationVector()), 0.0, 1e-15);  // no moment: no turn
}

// A body held along z at a speed and with its rotation stopped, pushed by a force and a moment:
// the held components keep their values, the free ones follow the force, the hold's reaction is
// the opposite of the held part of the load, and its work is the reaction's impulse times the
// held speed (W = -F_z t v_z for a steady push).
TEST(RigidBody, AHeldBodyKeepsItsHeldMotionAndReportsTheHoldsReaction) {
  RigidBody b = box();
  b.setMotion({1.0, 0.0, 3.0}, {0.5, -0.2, 0.1});
  RigidHold hold;
  hold.translation = {false, false, true};
  hold.rotation = true;
  hold.velocity = {0.0, 0.0, -2.0};
  b.setHold(hold);
  EXPECT_EQ(b.centreVelocity()[2], -2.0);  // from the start
  EXPECT_EQ(norm(b.angularVelocity()), 0.0);
  const Vec3 F = {10.0, -4.0, 30.0}, T = {1.0, 2.0, -3.0};
  const double h = 1e-3, m = b.mass();
  const int steps = 200;
  for (int n = 0; n < steps; ++n) {
    b.kick(F, T, h / 2);
    b.drift(h);
    b.kick(F, T, h / 2);
  }
  const double t = steps * h;
  EXPECT_EQ(b.centreVelocity()[2], -2.0);
  EXPECT_EQ(norm(b.angularVelocity()), 0.0);
  EXPECT_NEAR(b.centreVelocity()[0], 1.0 + F[0] / m * t, 1e-12);
  EXPECT_NEAR(b.centreVelocity()[1], F[1] / m * t, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.reactionMoment()[k], -T[k], 1e-12) << k;
  // the reaction m (v - (v + F h/2m)) / (h/2): the rounding of v + F h/2m, eps |v|, times 2m/h
  EXPECT_NEAR(b.reactionForce()[2], -F[2], 4 * 2.2e-16 * 2.0 * m / (h / 2));
  EXPECT_EQ(b.reactionForce()[0], 0.0);
  EXPECT_NEAR(b.holdWork(), -F[2] * t * -2.0, 2 * steps * 4 * 2.2e-16 * 2.0 * m * 2.0);
  EXPECT_NEAR(norm(b.rotationVector()), 0.0, 1e-15);
}

// Opposite forces at two corners: no resultant, a moment (x1 - x2) x f about any point; one kick
// of h adds h times it to the angular momentum and nothing to the momentum.
TEST(RigidBody, ACoupleTurnsTheBodyByItsMoment) {
  RigidBody b = box();
  const std::vector<Vec3> X = corners();
  const Vec3 f = {0.0, 5.0, 1.0}, minus = {0.0, -5.0, -1.0};
  const Vec3 T = {b.momentOf(X[1], f)[0] + b.momentOf(X[6], minus)[0], b.momentOf(X[1], f)[1] + b.momentOf(X[6], minus)[1],
                  b.momentOf(X[1], f)[2] + b.momentOf(X[6], minus)[2]};
  const Vec3 couple = cross(X[1] - X[6], f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(T[k], couple[k], 1e-14);
  b.kick({0, 0, 0}, T, 0.01);
  const Vec3 L = b.angularMomentum();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(L[k], 0.01 * couple[k], 1e-15);
  EXPECT_EQ(norm(b.momentum()), 0.0);
  EXPECT_GT(norm(b.angularVelocity()), 0.0);
}

TEST(RigidBody, ItsStateSurvivesACheckpointBitForBit) {
  RigidBody a = box(), b = box();
  a.setMotion({0.3, -1.0, 2.0}, {4.0, 1.0, -7.0});
  for (int n = 0; n < 10; ++n) a.kick({1, 2, 3}, {0.1, 0.2, -0.3}, 1e-3), a.drift(1e-3);
  b.restore(a.state());
  for (int n = 0; n < 10; ++n) {
    a.kick({1, 2, 3}, {0.1, 0.2, -0.3}, 1e-3), a.drift(1e-3);
    b.kick({1, 2, 3}, {0.1, 0.2, -0.3}, 1e-3), b.drift(1e-3);
  }
  EXPECT_EQ(a.state(), b.state());
  EXPECT_THROW(b.restore({1.0, 2.0}), std::invalid_argument);
}

// Points on one line have no inertia about it: such a body cannot turn and is refused.
TEST(RigidBody, ABodyWithoutInertiaAboutAnAxisIsRefused) {
  MassPropertiesSum line({0, 0, 0});
  line.addPoint({0, 0, 0}, 1.0);
  line.addPoint({1, 0, 0}, 1.0);
  EXPECT_THROW(RigidBody("rod", line.properties()), std::invalid_argument);
}

}  // namespace
}  // namespace choc
