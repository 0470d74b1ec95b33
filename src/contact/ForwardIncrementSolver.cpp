#include "contact/ForwardIncrementSolver.hpp"

#include <algorithm>
#include <cmath>

namespace choc {

ForwardIncrementResult solveForwardIncrement(const std::vector<std::vector<std::pair<int, double>>>& terms,
                                             const std::vector<double>& gaps,
                                             const std::vector<double>& inverseMass, double h2,
                                             int maxSweeps, bool unilateral) {
  const std::vector<double>& w = inverseMass;
  const size_t nS = terms.size();
  ForwardIncrementResult out;
  std::vector<double>& lam = out.lambda;
  lam.assign(nS, 0.0);
  std::vector<double> diag(nS, 0.0), shift(w.size(), 0.0);
  double scale = 0.0;
  for (size_t s = 0; s < nS; ++s) {
    for (const auto& [k, c] : terms[s]) diag[s] += h2 * c * c * w[k];
    scale = std::max(scale, std::abs(gaps[s]));
  }
  const double tol = 1e-12 * scale;
  for (; out.sweeps < maxSweeps; ++out.sweeps) {
    double change = 0.0;  // largest change of a gap in this sweep [m]
    for (size_t s = 0; s < nS; ++s) {
      if (!(diag[s] > 0)) continue;
      double r = gaps[s];
      for (const auto& [k, c] : terms[s]) r += c * shift[k];
      const double next = unilateral ? std::max(0.0, lam[s] - r / diag[s]) : lam[s] - r / diag[s];
      const double d = next - lam[s];
      if (d == 0.0) continue;
      for (const auto& [k, c] : terms[s]) shift[k] += h2 * w[k] * c * d;
      lam[s] = next;
      change = std::max(change, std::abs(d) * diag[s]);
    }
    if (change <= tol) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace choc
