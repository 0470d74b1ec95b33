#include "timeint/StabilityPolicy.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/Format.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

double explicitCriticalStep(double omegaMax, double xiMax) {
  if (!(omegaMax > 0)) return std::numeric_limits<double>::infinity();
  return 2.0 / omegaMax * (std::sqrt(1.0 + xiMax * xiMax) - xiMax);
}

const std::vector<std::string>& stabilityCheckNames() {
  static const std::vector<std::string> names = {"refuse", "warn", "substep"};
  return names;
}

StabilityCheck stabilityCheckFromName(const std::string& name) {
  if (name == "refuse") return StabilityCheck::Refuse;
  if (name == "warn") return StabilityCheck::Warn;
  if (name == "substep") return StabilityCheck::Substep;
  throw std::invalid_argument("unknown stability check '" + name + "'");
}

void declareStabilityCheck(Teuchos::ParameterList& p) {
  declareChoice(p, "Stability Check", "refuse", stabilityCheckNames(),
                "explicit schemes: when 'Time Step' exceeds the stable step (the critical step "
                "2/omega_max (sqrt(1 + xi^2) - xi) of a bound of the highest frequency, or a share "
                "of it when penalty springs switch on and off and would create energy above it: "
                "0.5 with penalty shock links, 0.15 with penalty contact): refuse the run, warn and go on, or cut each step into equal "
                "sub-steps at 0.9 of the stable step");
}

namespace {

// "", "half " or "0.15 of ": the share as the refusal words it before "the critical step".
std::string shareWords(double share) {
  if (share == 1) return "";
  return share == 0.5 ? "half " : shortNumber(share) + " of ";
}

}  // namespace

double stableShare(Switching switching) {
  if (switching == Switching::PenaltyContact) return kPenaltyContactShare;
  return switching == Switching::PenaltyLinks ? kPenaltyLinkShare : 1.0;
}

StabilityDecision decideStability(double dt, double criticalStep, Switching switching, StabilityCheck check) {
  StabilityDecision d;
  const double share = stableShare(switching);
  d.stableStep = share * criticalStep;
  // Closer than 1e-6 to the stable step counts as above it; a step written at 1 - 1e-6 of it
  // (SDNL111 A's rigid-link input) passes, to the round-off of the bound it was computed from.
  if (dt <= d.stableStep * (1 - 1e-6) * (1 + 1e-12)) return d;
  d.above = true;
  d.reason = format("%s s exceeds the stable step of the explicit scheme, %s s (%sthe critical step %s s)",
                    shortNumber(dt).c_str(), shortNumber(d.stableStep).c_str(),
                    shareWords(share).c_str(), shortNumber(criticalStep).c_str());
  if (switching == Switching::PenaltyLinks) d.reason += "; penalty links chatter above half of it";
  if (switching == Switching::PenaltyContact)
    d.reason += "; penalty contact creates energy above 0.15 of it (Lagrange contact needs no share)";
  d.refused = check == StabilityCheck::Refuse;
  d.warned = check == StabilityCheck::Warn;
  if (check == StabilityCheck::Substep) {
    const double n = std::ceil(dt / (kSubstepSafety * d.stableStep));
    d.substeps = n < double(std::numeric_limits<int>::max()) ? static_cast<int>(n)
                                                              : std::numeric_limits<int>::max();
  }
  return d;
}

}  // namespace choc
