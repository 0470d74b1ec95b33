#include "observers/HourglassMonitor.hpp"

#include <cstdio>

#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

void HourglassMonitor::update(double t, double hourglass, double material, double reference, bool quiet) {
  if (!(material > kSignificant * reference) || !(hourglass > 0)) return;
  const double ratio = hourglass / material;
  if (ratio > worst_) worst_ = ratio, worstTime_ = t;
  if (ratio <= kWarning || warned_) return;
  warned_ = true;
  if (quiet) return;
  char b[480];
  std::snprintf(b, sizeof b,
                "  warning: %s: hourglass energy %.3g %% of the strain and plastic energy at t = %.6e s (above %g %%; "
                "past %g %% the run fails a check): the hourglass control carries load the material should; lower "
                "'Hourglass Coefficient' or use 'Formulation' = 'F-bar'\n",
                what_.c_str(), 100 * ratio, t, 100 * kWarning, 100 * kLimit);
  log() << b;
}

CheckResult HourglassMonitor::checkResult(const std::string& analysis) const {
  CheckSpec spec;
  spec.analysis = analysis;
  spec.quantity = "energy:hourglass / (energy:strain + energy:plastic), largest";
  spec.time = worstTime_;
  spec.reference = 0.0;
  spec.kind = ReferenceKind::Exact;
  spec.criterion = Criterion::Absolute;
  spec.tolerance = kLimit;
  spec.note = "the one-point elements' hourglass control carries the load (lower 'Hourglass Coefficient' or use F-bar)";
  return evaluateCheck(spec, worst_);
}

}  // namespace choc
