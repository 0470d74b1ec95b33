#include "reference/HistoryError.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace choc {
namespace {

std::string show(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

HistoryError historyError(const std::vector<double>& times, const std::vector<double>& values,
                          const std::function<double(double)>& exact,
                          std::optional<double> peak) {
  if (times.size() != values.size())
    throw std::invalid_argument("history error: " + std::to_string(times.size()) + " times but " +
                                std::to_string(values.size()) + " values");
  if (times.empty()) throw std::invalid_argument("history error: no sample");
  if (!exact) throw std::invalid_argument("history error: no reference function");
  if (peak && !(std::isfinite(*peak) && *peak > 0.0))
    throw std::invalid_argument("history error: supplied peak " + show(*peak) +
                                " is not a positive finite number");

  HistoryError e;
  e.samples = times.size();
  double sumSq = 0.0, maxExact = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i], y = values[i];
    if (!std::isfinite(t))
      throw std::invalid_argument("history error: time #" + std::to_string(i) + " is " + show(t));
    if (!std::isfinite(y))
      throw std::invalid_argument("history error: value at t = " + show(t) + " is " + show(y));
    const double r = exact(t);
    if (!std::isfinite(r))
      throw std::invalid_argument("history error: reference at t = " + show(t) + " is " + show(r));
    const double d = std::abs(y - r);
    if (d > e.maxAbs || i == 0) {
      e.maxAbs = d;
      e.timeOfMax = t;
    }
    sumSq += d * d;
    maxExact = std::max(maxExact, std::abs(r));
  }
  e.rms = std::sqrt(sumSq / static_cast<double>(times.size()));
  e.peak = peak ? *peak : maxExact;
  if (!(e.peak > 0.0))
    throw std::invalid_argument("history error: the reference is 0 at every sample; supply a "
                                "peak to get relative errors");
  e.maxRelPeak = e.maxAbs / e.peak;
  e.rmsRelPeak = e.rms / e.peak;
  return e;
}

}  // namespace choc
