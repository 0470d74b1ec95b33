#include "timeint/ModalStepper.hpp"

namespace choc {

ModalStepper::ModalStepper(const ModalIntegrator& integrator, ModalState& state, double t0, int substeps,
                           Hooks hooks)
    : integrator_(integrator), state_(state), t0_(t0), substeps_(substeps), hooks_(std::move(hooks)) {}

void ModalStepper::start(double t0, double firstStep, TransientSummary& sum, StepInfo& /*info*/) {
  integrator_.initialize(state_, t0);
  sum.smallestStep = firstStep;
}

// The whole nominal step (its own length: dt, or the last one cut to the end time) in the
// sub-steps the stability policy asked for, times the adaptive scheme's refinement.
Advance ModalStepper::advance(const NominalStep& s, StepControl& /*c*/, TransientSummary& /*sum*/) {
  integrator_.advance(state_, s.length, substeps_, hooks_.substep);
  state_.t = s.target;
  Advance a;
  a.time = s.target;
  a.dt = s.length;
  return a;
}

void ModalStepper::archiveState(StateArchive& a, const StateVectors& vectors) const {
  integrator_.archive(state_, a);
  if (hooks_.archive) hooks_.archive(a, vectors);
}

// The integrator starts as for a new run (the links' force evaluated once), then takes the
// checkpoint's state.
void ModalStepper::restoreState(const StateArchive& a, const StateVectors& vectors) {
  integrator_.initialize(state_, t0_);
  integrator_.restore(state_, a);
  if (hooks_.restore) hooks_.restore(a, vectors);
}

}  // namespace choc
