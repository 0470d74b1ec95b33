#include "analysis/Analysis.hpp"

namespace choc {

bool RunContext::failedChecks() const {
  for (const auto& c : checks)
    if (!c.ok) return true;
  return false;
}

}  // namespace choc
