// The forward-increment pressures of exactly enforced contact in an explicit step (Carpenter,
// Taylor and Katona 1991): the explicit solver layer of contact, apart from the geometry and
// the active set. For constraints s with terms (k, c_sk) over the contact DOFs k, the gaps g_s
// of the predicted positions, the inverse masses w_k of those DOFs and the factor h2 by which
// an acceleration moves a position, the pressures lambda solve the complementarity problem
//   g_s + sum_k c_sk h2 w_k sum_r c_rk lambda_r >= 0,   lambda_s >= 0,   complementary,
// by projected Gauss-Seidel on h2 B M^-1 B^T (one sweep when no two constraints share a DOF:
// against obstacles). Converged when no sweep changes a gap by more than 1e-12 of the largest
// |g_s|. Bilateral (unilateral = false): lambda of either sign with every g_s brought to 0
// (Gauss-Seidel on the same matrix).
#pragma once
#include <utility>
#include <vector>

namespace choc {

struct ForwardIncrementResult {
  std::vector<double> lambda;  // per constraint, >= 0
  int sweeps = 0;
  bool converged = false;
};

// terms[s]: (index into the contact DOFs, coefficient) of constraint s; gaps[s]; inverseMass[k].
ForwardIncrementResult solveForwardIncrement(const std::vector<std::vector<std::pair<int, double>>>& terms,
                                             const std::vector<double>& gaps,
                                             const std::vector<double>& inverseMass, double h2,
                                             int maxSweeps = 1000, bool unilateral = true);

}  // namespace choc
