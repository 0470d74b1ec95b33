// What the steppers of a SecondOrderOperator (NewmarkStepper, CentralDifferenceStepper) share:
// the accepted state (u, v, a) on the operator's map, the observers that see it, and its
// checkpoint records ("driver/u", "driver/v", "driver/a" and the operator's own state).
#pragma once
#include <string>
#include <vector>

#include "timeint/SecondOrderOperator.hpp"
#include "timeint/StepLoop.hpp"

namespace choc {

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // Called for the initial state (step 0) and after every accepted step.
  virtual void stepAccepted(const StepInfo& info, const Vector& u, const Vector& v,
                            const Vector& a) = 0;
  // Explicit sub-steps inside a step (not its last, which stepAccepted reports): for what
  // integrates over every state the scheme computes (impact statistics).
  virtual void substepTaken(double /*time*/, const Vector& /*u*/, const Vector& /*v*/) {}
};

class StructuralStepper : public Stepper {
 public:
  void addObserver(StepObserver* o) { observers_.push_back(o); }
  // The initial displacement and velocity (at the grid's start).
  void setInitialState(const Vector& u, const Vector& v);
  const Vector& displacement() const { return *u_; }
  const Vector& velocity() const { return *v_; }
  // The grid of the settings: the one loop over this stepper from (u, v) at startTime to
  // endTime (or from `resume`); u and v hold the final state on return. Throws NumericalError
  // when a step fails beyond what the stepper can do.
  TransientSummary run(Vector& u, Vector& v, const StepLoop::Resume* resume = nullptr);

  void notify(const StepInfo& info) override;
  void archiveState(StateArchive& a, const StateVectors& vectors) const override;
  void restoreState(const StateArchive& a, const StateVectors& vectors) override;

 protected:
  StructuralStepper(SecondOrderOperator& op, TransientSettings settings);
  void notifySubstep(double t);
  // The operator's validity of u at time t: its warning logged once in the run, its failure
  // returned ("" when u is in the model's domain). Collective.
  std::string checkValidity(const Vector& u, double t);

  SecondOrderOperator& op_;
  TransientSettings s_;
  RCP<Vector> u_, v_, a_;  // the accepted state
  std::vector<StepObserver*> observers_;
  bool validityWarned_ = false;
};

}  // namespace choc
