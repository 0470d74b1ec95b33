// The central-difference stepper (explicit; Newmark beta = 0, gamma = 1/2) over an
// ExplicitOperator with a diagonal (lumped) mass: no linear solve. With half-step velocities,
//   a_n = -M^-1 (F(u_n, v*, t_n) + f_c(u_n, v*)),   v* = v_{n-1/2} (damping and dashpots lag
//   half a step, the usual explicit treatment),
//   v_{n+1/2} = v_{n-1/2} + dt a_n,   u_{n+1} = u_n + dt v_{n+1/2},
// and v_n = v_{n-1/2} + dt/2 a_n for the output. The constraint status (penalty contact) is
// re-evaluated at every u_n before its forces; exactly enforced contact (Lagrange) takes
// forward-increment multipliers: a_n includes M^-1 B^T lambda_n such that u_{n+1} has no
// negative gap (ExplicitOperator::addExplicitContact). A nominal step longer than the stable
// step is cut into `substeps` equal sub-steps (the stability policy decides them:
// timeint/StabilityPolicy.hpp; physics/ExplicitPlan.hpp). Observers see every nominal step's
// end state, and each sub-step's as a sub-step.
#pragma once
#include <functional>

#include "timeint/ExplicitOperator.hpp"
#include "timeint/RigidMotion.hpp"
#include "timeint/StructuralStepper.hpp"

namespace choc {

class CentralDifferenceStepper : public StructuralStepper {
 public:
  // inverseMass: 1 / M_ii on the operator's map (every entry finite and positive).
  CentralDifferenceStepper(ExplicitOperator& op, RCP<const Vector> inverseMass, TransientSettings settings,
                           int substeps);
  int substeps() const { return substeps_; }
  // A model whose stiffness changes with its state (finite strain): every `interval` nominal
  // steps (and at the first), `decide(u, t, n)` returns the sub-steps per step for the current
  // configuration (or throws). The count is in the checkpoints.
  using SubstepDecision = std::function<int(const Vector& u, double t, long long n)>;
  void monitorStability(int interval, SubstepDecision decide) {
    interval_ = interval;
    decide_ = std::move(decide);
  }
  // Every `interval` steps (and at the first), the operator's validity of the accepted state
  // (SecondOrderOperator::validity): a failure stops the run (InadmissibleState), a warning is
  // logged once.
  void checkValidityEvery(int interval) { validityEvery_ = interval; }
  // The rigid bodies (their rows' inverse mass 0): placed after each drift, moved by their
  // rows' forces (timeint/RigidMotion.hpp); null: none.
  void moveRigidBodies(RigidMotion* bodies) { rigid_ = bodies; }
  void archiveState(StateArchive& a, const StateVectors& vectors) const override;
  void restoreState(const StateArchive& a, const StateVectors& vectors) override;

  void start(double t0, double firstStep, TransientSummary& sum, StepInfo& info) override;
  // The nominal step in `substeps` sub-steps; throws NumericalError when the state stops
  // being finite (naming the stability limit).
  Advance advance(const NominalStep& s, StepControl& c, TransientSummary& sum) override;

 private:
  // a = -M^-1 (F(u, vStar, t) + f_c(u, vStar)) with the status updated at u; with exactly
  // enforced contact, plus the contact accelerations that keep the next position, u + h vStar
  // + factor h^2 a, from penetrating (forward increments: factor 1/2 from an integer-step
  // velocity at the start, 1 from a half-step velocity).
  void acceleration(const Vector& u, const Vector& vStar, double t, double dt, Vector& a,
                    double h, double factor);
  void takeSubsteps(double t, double target, double h);
  void requireFiniteState(double t, long long n) const;

  ExplicitOperator& xop_;
  RCP<const Vector> inverseMass_;
  int substeps_ = 1;
  int interval_ = 0;
  int validityEvery_ = 0;  // steps between validity checks (0: none)
  SubstepDecision decide_;
  RigidMotion* rigid_ = nullptr;
  RCP<Vector> vHalf_, r_, uStar_;
};

}  // namespace choc
