// The stability policy of the explicit schemes (central differences, symplectic Euler, the
// modal transient's schemes), one for every transient.
//
// The critical step of an undamped explicit scheme is 2/omega_max, reduced for the damping
// ratio xi at omega_max: 2/omega_max (sqrt(1 + xi^2) - xi). The stable step is the critical
// step, or a share of it when penalty springs switch on and off during the run: half of it
// with penalty shock links (near the limit they chatter and create energy, measured on SDNL111
// D's scene at 0.85 of it); 0.15 of it with penalty contact on a meshed surface (each release
// of a contact node returns more energy than its entry stored, about (omega dt)^2 of the node's
// share: the copper bar at 227 m/s on a rigid plane creates 0.70 % of its energy with sub-steps
// at 0.43 of the critical step, 0.26 % at 0.35, 0.10 % at 0.17, 0.05 % at 0.135; forward-
// increment Lagrange contact creates none and needs no share). A step closer than 1e-6
// (relative) to the stable step counts as above // it (at the limit itself the highest mode grows linearly). Above it, 'Stability Check':
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

// What switches on and off during the run: nothing, penalty shock links, penalty contact.
enum class Switching { None, PenaltyLinks, PenaltyContact };
// The stable step's share of the critical step: 1, 0.5 (links), 0.15 (contact; the smaller with both).
double stableShare(Switching switching);

struct StabilityDecision {
  double stableStep = 0;  // the critical step's share (stableShare)
  int substeps = 1;
  bool above = false;     // dt above the stable step
  bool refused = false;   // above, and 'refuse': the caller reports `reason` as an input error
  bool warned = false;    // above, and 'warn': the caller logs `reason`
  std::string reason;     // "exceeds the stable step ..." when above
};

StabilityDecision decideStability(double dt, double criticalStep, Switching switching, StabilityCheck check);

// The sub-steps' safety factor (0.9) and the switching springs' shares of the critical step.
constexpr double kSubstepSafety = 0.9;
constexpr double kPenaltyLinkShare = 0.5;
constexpr double kPenaltyContactShare = 0.15;

}  // namespace choc
