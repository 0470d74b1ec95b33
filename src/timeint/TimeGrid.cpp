#include "timeint/TimeGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace choc {

double nominalSteps(double start, double end, double dt) {
  const double ratio = (end - start) / dt;
  if (!(dt > 0) || !std::isfinite(ratio)) return std::numeric_limits<double>::infinity();
  return std::max(1.0, std::ceil(ratio - 1e-9));
}

TimeGrid::TimeGrid(double start, double end, double dt) : start_(start), end_(end), dt_(dt) {
  const double count = nominalSteps(start, end, dt);
  if (!(end > start) || !(count <= kLargestStepCount))
    throw std::invalid_argument("TimeGrid: needs dt > 0, end > start and a finite step count");
  const double ratio = (end - start) / dt;
  const double whole = std::round(ratio);
  if (whole >= 1 && std::abs(ratio - whole) <= 1e-6 * std::max(1.0, ratio)) {
    steps_ = static_cast<long long>(whole);
    lastStep_ = dt;
  } else {
    steps_ = static_cast<long long>(count);
    lastStep_ = end - start - double(steps_ - 1) * dt;
  }
}

}  // namespace choc
