#include "timeint/TimeGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace choc {

double nominalSteps(double start, double end, double dt) {
  const double ratio = (end - start) / dt;
  if (!(dt > 0) || !std::isfinite(ratio)) return std::numeric_limits<double>::infinity();
  return std::max(1.0, std::ceil(ratio - 1e-9));
}

}  // namespace choc
