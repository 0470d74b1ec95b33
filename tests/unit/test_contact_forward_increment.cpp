// The forward-increment pressures (contact/ForwardIncrementSolver.hpp) on small problems whose
// solution is known: the complementarity conditions hold at the returned pressures, and the
// projected Gauss-Seidel reports when it runs out of sweeps.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "contact/ForwardIncrementSolver.hpp"
#include "core/Vec3.hpp"

namespace choc {
namespace {

using Terms = std::vector<std::vector<std::pair<int, double>>>;

// The gaps after the increments: g_s + sum_k c_sk h2 w_k sum_r c_rk lambda_r.
std::vector<double> gapsAfter(const Terms& terms, const std::vector<double>& g, const std::vector<double>& w,
                              double h2, const std::vector<double>& lambda) {
  std::vector<double> shift(w.size(), 0.0), out = g;
  for (size_t r = 0; r < terms.size(); ++r)
    for (const auto& [k, c] : terms[r]) shift[k] += h2 * w[k] * c * lambda[r];
  for (size_t s = 0; s < terms.size(); ++s)
    for (const auto& [k, c] : terms[s]) out[s] += c * shift[k];
  return out;
}

void expectComplementarity(const Terms& terms, const std::vector<double>& g, const std::vector<double>& w,
                           double h2, const ForwardIncrementResult& r) {
  ASSERT_TRUE(r.converged);
  const std::vector<double> after = gapsAfter(terms, g, w, h2, r.lambda);
  double scale = 0;
  for (double x : g) scale = std::max(scale, std::abs(x));
  for (size_t s = 0; s < g.size(); ++s) {
    EXPECT_GE(r.lambda[s], 0.0) << s;
    // The stopping test bounds each sweep's change of a gap by 1e-12 of the largest gap; the
    // remaining error of a gap is of that order times the coupling's condition (here < 10).
    EXPECT_GE(after[s], -1e-10 * scale) << s;
    if (r.lambda[s] > 0) EXPECT_NEAR(after[s], 0.0, 1e-10 * scale) << s;
  }
}

TEST(ForwardIncrement, AnObstacleConstraintTakesOneSweep) {
  // Two slave DOFs against an obstacle (no shared DOF): lambda_s = -g_s / (h2 c^2 w) where closed.
  const Terms terms = {{{0, 1.0}}, {{1, 1.0}}};
  const std::vector<double> g = {-2e-6, 3e-6}, w = {0.5, 0.25};
  const double h2 = 1e-12;
  const ForwardIncrementResult r = solveForwardIncrement(terms, g, w, h2);
  expectComplementarity(terms, g, w, h2, r);
  EXPECT_NEAR(r.lambda[0], 2e-6 / (h2 * 0.5), 1e-9 * 2e-6 / (h2 * 0.5));
  EXPECT_EQ(r.lambda[1], 0.0);  // open: no pressure
  EXPECT_LE(r.sweeps, 1);
}

TEST(ForwardIncrement, ConstraintsSharingAMasterDofAreCoupled) {
  // Two slave nodes on one master DOF (weights 0.5 each): the pressures interact; both close.
  const Terms terms = {{{0, 1.0}, {2, -0.5}}, {{1, 1.0}, {2, -0.5}}};
  const std::vector<double> g = {-1e-6, -3e-6}, w = {1.0, 1.0, 0.2};
  const double h2 = 1e-10;
  const ForwardIncrementResult r = solveForwardIncrement(terms, g, w, h2);
  expectComplementarity(terms, g, w, h2, r);
  EXPECT_GT(r.lambda[0], 0.0);
  EXPECT_GT(r.lambda[1], 0.0);
  EXPECT_GT(r.sweeps, 1);
}

TEST(ForwardIncrement, ASweepLimitIsReportedNotHidden) {
  const Terms terms = {{{0, 1.0}, {2, -0.5}}, {{1, 1.0}, {2, -0.5}}};
  const std::vector<double> g = {-1e-6, -3e-6}, w = {1.0, 1.0, 0.2};
  const ForwardIncrementResult r = solveForwardIncrement(terms, g, w, 1e-10, 1);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.sweeps, 1);
}

// The gaps after the increments when DOFs 0 and 1 belong to one rigid body (levers r0, r1, their
// components z): the pressures' force and moment on the body move it by h2 (F / m, I^-1 T),
// which moves its DOFs by e_k . (dV + dW x r_k); the others by h2 w_k c lambda.
std::vector<double> gapsAfterWithBody(const Terms& terms, const std::vector<double>& g, const std::vector<double>& w,
                                      const RigidContactBodies& body, double h2, const std::vector<double>& lambda) {
  std::vector<double> shift(w.size(), 0.0), out = g;
  Vec3 F{}, T{};
  for (size_t r = 0; r < terms.size(); ++r)
    for (const auto& [k, c] : terms[r]) {
      const RigidContactDof& d = body.dofs[size_t(k)];
      if (d.body < 0) {
        shift[size_t(k)] += h2 * w[size_t(k)] * c * lambda[r];
        continue;
      }
      Vec3 f{};
      f[size_t(d.component)] = c * lambda[r];
      const Vec3 m = cross(d.lever, f);
      for (int i = 0; i < 3; ++i) F[size_t(i)] += f[size_t(i)], T[size_t(i)] += m[size_t(i)];
    }
  const auto& J = body.inverseInertia[0];
  const Vec3& wb = body.inverseMass[0];
  const Vec3 dV = {h2 * wb[0] * F[0], h2 * wb[1] * F[1], h2 * wb[2] * F[2]};
  const Vec3 dW = {h2 * (J[0] * T[0] + J[1] * T[1] + J[2] * T[2]), h2 * (J[3] * T[0] + J[4] * T[1] + J[5] * T[2]),
                   h2 * (J[6] * T[0] + J[7] * T[1] + J[8] * T[2])};
  for (size_t k = 0; k < w.size(); ++k) {
    const RigidContactDof& d = body.dofs[k];
    if (d.body < 0) continue;
    const Vec3 turn = cross(dW, d.lever);
    shift[k] = dV[size_t(d.component)] + turn[size_t(d.component)];
  }
  for (size_t s = 0; s < terms.size(); ++s)
    for (const auto& [k, c] : terms[s]) out[s] += c * shift[size_t(k)];
  return out;
}

TEST(ForwardIncrement, ARigidBodysDofsMoveTogether) {
  // Two nodes of one rigid body (DOFs 0 and 1, component z, off its centre) pressed against two
  // deformable DOFs (2 and 3): the body's translation and rotation couple the constraints,
  // both close exactly (pressing the second alone would lift the first by 1.3e-6 only), and the body's DOFs have no inverse mass of their own.
  const Terms terms = {{{0, 1.0}, {2, -1.0}}, {{1, 1.0}, {3, -1.0}}};
  const std::vector<double> g = {-2e-6, -3e-6}, w = {0.0, 0.0, 0.5, 0.5};
  RigidContactBodies body;
  body.dofs = {{0, 2, {0.1, 0.0, 0.0}}, {0, 2, {-0.1, 0.05, 0.0}}, {}, {}};
  body.inverseMass = {{0.5, 0.5, 0.5}};
  body.inverseInertia = {{2.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 1.0}};
  const double h2 = 1e-8;
  const ForwardIncrementResult r = solveForwardIncrement(terms, g, w, h2, 1000, true, &body);
  ASSERT_TRUE(r.converged);
  const std::vector<double> after = gapsAfterWithBody(terms, g, w, body, h2, r.lambda);
  for (size_t s = 0; s < 2; ++s) {
    EXPECT_GT(r.lambda[s], 0.0) << s;
    EXPECT_NEAR(after[s], 0.0, 1e-10 * 3e-6) << s;
  }
  // Without the body, the same DOFs would not move (w = 0): the deformable side takes it all.
  const ForwardIncrementResult alone = solveForwardIncrement(terms, g, w, h2);
  EXPECT_NEAR(alone.lambda[0], 2e-6 / (h2 * 0.5), 1e-9 * 2e-6 / (h2 * 0.5));
  EXPECT_LT(r.lambda[1], alone.lambda[1]);  // the body gives way: less pressure
}

}  // namespace
}  // namespace choc
