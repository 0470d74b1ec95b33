// The forward-increment pressures (contact/ForwardIncrementSolver.hpp) on small problems whose
// solution is known: the complementarity conditions hold at the returned pressures, and the
// projected Gauss-Seidel reports when it runs out of sweeps.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "contact/ForwardIncrementSolver.hpp"

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

}  // namespace
}  // namespace choc
