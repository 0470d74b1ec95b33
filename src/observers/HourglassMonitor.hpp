// The one-point elements' hourglass energy against the material's energy (energy:strain +
// energy:plastic). Past 10 % of it the hourglass control, not the material, carries the load
// (docs/user-guide/plasticity.md): the answer is the control's. The monitor warns once on the
// log when the ratio passes kWarning (half that alarm) and makes a run whose ratio passes kLimit
// (the alarm) a failed check (a row in checks.csv, exit 3), as energy created is. Judged only
// where the material's energy is at least 1 % of the run's reference energy, so that the first
// steps of an impact (both energies near zero) do not decide.
#pragma once
#include <string>

#include "output/Checks.hpp"

namespace choc {

class HourglassMonitor {
 public:
  static constexpr double kWarning = 0.05, kLimit = 0.10, kSignificant = 0.01;

  explicit HourglassMonitor(std::string what) : what_(std::move(what)) {}
  // One recorded state: the hourglass energy, the material's (strain + plastic, the hourglass's
  // included) and the reference energy of the run (E0 or the largest total so far).
  // `quiet`: a state recorded before a restart (no second warning).
  void update(double t, double hourglass, double material, double reference, bool quiet = false);
  bool failed() const { return worst_ > kLimit; }
  CheckResult checkResult(const std::string& analysis) const;
  double worst() const { return worst_; }

 private:
  std::string what_;
  bool warned_ = false;
  double worst_ = 0.0, worstTime_ = 0.0;
};

}  // namespace choc
