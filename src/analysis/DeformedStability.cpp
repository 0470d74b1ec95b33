#include "analysis/DeformedStability.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

double DeformedStability::omegaAt(double lambda) {
  if (lambda0_ < 0) lambda0_ = lambda;
  const double mesh = plan_.meshBound;
  if (!std::isfinite(mesh))
    return lambda0_ > 0 ? plan_.bound.omegaMax * std::sqrt(std::max(1.0, lambda / lambda0_)) : plan_.bound.omegaMax;
  if (lambda <= mesh) return plan_.bound.omegaMax;
  const double couplings = std::max(0.0, plan_.bound.element * plan_.bound.element - mesh);
  return std::sqrt(lambda + couplings);
}

int DeformedStability::operator()(const Vector& u, double t, long long n) {
  const double w = omegaAt(op_.internalForce().stateEigenvalueBound(u));
  const double xi = w > 0 ? 0.5 * (rayleighK_ * w + rayleighM_ / w) : 0.0;
  const double critical = explicitCriticalStep(w, xi);
  const StabilityDecision d = decideStability(timeStep_, critical, plan_.switching, check_);
  if (d.refused)
    throw NumericalError(label_ + format(": at t = %.6e s (step %lld) the deformed mesh's highest frequency is at most "
                                         "%.4e rad/s: ",
                                         t, n, w) +
                         d.reason + "; lower 'Time Step' or set 'Stability Check' = 'substep'");
  if (d.warned && !warned_) {
    log() << "choc: warning: " << label_ << format(": at t = %.6e s: ", t) << d.reason << "\n";
    warned_ = true;
  }
  if (substeps_ >= 0 && d.substeps != substeps_)
    log() << format("  t = %.6e s: the deformed mesh's stable step is %.4e s: %d sub-step(s) per step\n", t,
                    d.stableStep, d.substeps);
  substeps_ = d.substeps;
  return d.substeps;
}

}  // namespace choc
