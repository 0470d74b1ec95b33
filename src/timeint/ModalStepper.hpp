// The modal stepper: the modal integrators (timeint/ModalIntegrator.hpp: symplectic Euler,
// central differences, adaptive) on a basis' generalised system, behind the one step loop.
// The state is the modal coordinates; what the output sees of them (the basis' rows, the
// physical fields) and what a checkpoint adds (the basis' eigenvalues and the fields expanded
// on it) are the analysis' hooks.
#pragma once
#include <functional>

#include "timeint/ModalIntegrator.hpp"
#include "timeint/StepLoop.hpp"

namespace choc {

class ModalStepper : public Stepper {
 public:
  struct Hooks {
    std::function<void(const StepInfo&)> accepted;  // the state holds the step info reports
    std::function<void(double)> substep;            // a sub-step's end time (not the step's last)
    std::function<void(StateArchive&, const StateVectors&)> archive;  // the analysis' records
    std::function<void(const StateArchive&, const StateVectors&)> restore;
  };
  // substeps: per nominal step, from the stability policy. state holds the initial
  // coordinates and velocities at t0.
  ModalStepper(const ModalIntegrator& integrator, ModalState& state, double t0, int substeps, Hooks hooks);

  void start(double t0, double firstStep, TransientSummary& sum, StepInfo& info) override;
  Advance advance(const NominalStep& s, StepControl& c, TransientSummary& sum) override;
  void notify(const StepInfo& info) override { hooks_.accepted(info); }
  void archiveState(StateArchive& a, const StateVectors& vectors) const override;
  void restoreState(const StateArchive& a, const StateVectors& vectors) override;

 private:
  const ModalIntegrator& integrator_;
  ModalState& state_;
  double t0_;
  int substeps_;
  Hooks hooks_;
};

}  // namespace choc
