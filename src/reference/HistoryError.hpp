// Error of a computed time history against a reference function of time.
#pragma once
#include <functional>
#include <optional>
#include <vector>

namespace choc {

struct HistoryError {
  double maxAbs = 0.0;      // max_i |y_i - exact(t_i)|
  double rms = 0.0;         // sqrt(mean_i (y_i - exact(t_i))^2)
  double peak = 0.0;        // max_i |exact(t_i)|, or the supplied peak
  double maxRelPeak = 0.0;  // maxAbs / peak
  double rmsRelPeak = 0.0;  // rms / peak
  double timeOfMax = 0.0;   // the first t_i where maxAbs is reached
  std::size_t samples = 0;
};

// Throws std::invalid_argument when the sizes differ, there is no sample, a time, a value
// or an exact value is not finite, or the peak is not a positive finite number: a NaN never
// becomes an answer.
HistoryError historyError(const std::vector<double>& times, const std::vector<double>& values,
                          const std::function<double(double)>& exact,
                          std::optional<double> peak = std::nullopt);

}  // namespace choc
