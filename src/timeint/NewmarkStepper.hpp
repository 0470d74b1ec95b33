// The Newmark-family stepper (implicit) over a SecondOrderOperator: initial acceleration from
// equilibrium, one Newton/active-set solve per attempt, and the step control: a failed attempt
// (Newton or active set) is retried with dt cut by 'cutFactor' up to 'maxCuts' times inside
// the nominal step, then the run stops with a NumericalError naming the time and the reason.
// An attempt that did not converge is never passed to the observers.
#pragma once

#include <vector>

#include "timeint/NewmarkFamily.hpp"
#include "timeint/StructuralStepper.hpp"

namespace choc {

class NewmarkStepper : public StructuralStepper {
 public:
  NewmarkStepper(SecondOrderOperator& op, NewmarkFamily scheme, TransientSettings settings);
  const NewmarkFamily& scheme() const { return scheme_; }

  void start(double t0, double firstStep, TransientSummary& sum, StepInfo& info) override;
  Advance advance(const NominalStep& s, StepControl& c, TransientSummary& sum) override;
  void archiveState(StateArchive& a, const StateVectors& vectors) const override;
  void restoreState(const StateArchive& a, const StateVectors& vectors) override;
  // The local DOFs without inertia (the redistributed contact mass: their equations are static,
  // so the Newmark predictor, built from their velocity and acceleration that only close the
  // scheme's relations, carries no information): Newton starts them from their last two
  // increments extrapolated to the step. The solution is the same; a frictional contact layer's
  // stick and slip start near it (the block on the slab: 3.20 corrections per step against 5.35).
  void extrapolateMassless(std::vector<char> mask);

 private:
  // One attempt from the accepted state at t to t + dt; returns the outcome, leaves u1, v1, a1.
  // A state outside the model's domain (InadmissibleState: an inverted element) is a failed
  // attempt, cut like one that did not converge.
  NewtonOutcome attempt(double t, double dt);
  NewtonOutcome attemptWithin(double t, double dt);
  // The weighted terms M a_n and F_n of the next step (alpha schemes).
  void weightedTerms(double t);
  void countIterations(const NewtonOutcome& out, TransientSummary& sum) const;
  void rejectAttempt(double t, double h, int cuts, const NewtonOutcome& out, TransientSummary& sum);
  void acceptAttempt(double t, double dt);
  void startIterate(double dt);

  NewmarkFamily scheme_;
  // Weighted terms at t_n and the trial state at t_{n+1} (the accepted one is u_, v_, a_).
  RCP<Vector> Ma0_, F0_, Ma1_, F1_, u1_, v1_, a1_;
  RCP<Vector> uTilde_, vTilde_, inertia_, forces_, fc_, change_;
  // extrapolateMassless: the mask (empty: off); u_n - u_{n-1}, u_{n-1} - u_{n-2} and their steps
  // (0: none yet).
  std::vector<char> massless_;
  RCP<Vector> lastIncrement_, previousIncrement_;
  double lastStep_ = 0.0, previousStep_ = 0.0;
};

}  // namespace choc
