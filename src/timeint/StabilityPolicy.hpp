// The stability policy of the explicit schemes (central differences, symplectic Euler, the
// modal transient's schemes), one for every transient.
//
// The critical step of an undamped explicit scheme is 2/omega_max, reduced for the damping
// ratio xi at omega_max: 2/omega_max (sqrt(1 + xi^2) - xi). The stable step is the critical
// step, or half of it when penalty springs switch on and off during the run (penalty contact,
// penalty shock links: near the limit they chatter and create energy, measured on SDNL111 D's
// scene at 0.85 of it). A step closer than 1e-6 (relative) to the stable step counts as above
// it (at the limit itself the highest mode grows linearly). Above it, 'Stability Check':
//   refuse  (default) the input is refused, naming the stable step;
//   warn    the run goes on at the given step, with a warning (it may blow up: the energy
//           balance and the finiteness checks then stop it);
//   substep every step is cut into equal sub-steps of at most 0.9 of the stable step.
#pragma once
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace choc {

// 2/omega (sqrt(1 + xi^2) - xi); infinity when omega is not positive.
double explicitCriticalStep(double omegaMax, double xiMax);

enum class StabilityCheck { Refuse, Warn, Substep };
const std::vector<std::string>& stabilityCheckNames();  // refuse, warn, substep
StabilityCheck stabilityCheckFromName(const std::string& name);
// 'Stability Check' with the same choices and documentation in every transient.
void declareStabilityCheck(Teuchos::ParameterList& analysis);

struct StabilityDecision {
  double stableStep = 0;  // the critical step, or half of it with switching springs
  int substeps = 1;
  bool above = false;     // dt above the stable step
  bool refused = false;   // above, and 'refuse': the caller reports `reason` as an input error
  bool warned = false;    // above, and 'warn': the caller logs `reason`
  std::string reason;     // "exceeds the stable step ..." when above
};

// `switching`: penalty springs that switch on and off (penalty contact, penalty links).
StabilityDecision decideStability(double dt, double criticalStep, bool switching, StabilityCheck check);

// The sub-steps' safety factor (0.9) and the switching springs' share of the critical step (0.5).
constexpr double kSubstepSafety = 0.9;
constexpr double kSwitchingShare = 0.5;

}  // namespace choc
