#include "analysis/Analysis.hpp"

#include <cmath>

namespace choc {

double ModalBasis::frequencyHz(int mode) const {
  const double l = eigenvalues[mode];
  return l > 0 ? std::sqrt(l) / (2.0 * M_PI) : 0.0;
}

bool RunContext::failedChecks() const {
  for (const auto& c : checks)
    if (!c.ok) return true;
  return false;
}

}  // namespace choc
