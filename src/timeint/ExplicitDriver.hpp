// The step loop of explicit central differences (Newmark beta = 0, gamma = 1/2) over a
// SecondOrderOperator with a diagonal (lumped) mass: no linear solve. With half-step
// velocities,
//   a_n = -M^-1 (F(u_n, v*, t_n) + f_c(u_n, v*)),   v* = v_{n-1/2} (damping and dashpots lag
//   half a step, the usual explicit treatment),
//   v_{n+1/2} = v_{n-1/2} + dt a_n,   u_{n+1} = u_n + dt v_{n+1/2},
// and v_n = v_{n-1/2} + dt/2 a_n for the output. The constraint status (penalty contact) is
// re-evaluated at every u_n before its forces; exactly enforced contact (Lagrange) takes
// forward-increment multipliers: a_n includes M^-1 B^T lambda_n such that u_{n+1} has no
// negative gap (ExplicitOperator::addExplicitContact). A nominal step longer than the critical step is
// cut into `substeps` equal sub-steps (the caller decides, from its estimate of the highest
// frequency). Observers see every nominal step's end state (sub-steps are not reported).
#pragma once
#include <vector>

#include "timeint/ExplicitOperator.hpp"
#include "timeint/TransientDriver.hpp"

namespace choc {

class ExplicitDriver : public StepLoop {
 public:
  // inverseMass: 1 / M_ii on the operator's map (every entry finite and positive).
  ExplicitDriver(ExplicitOperator& op, RCP<const Vector> inverseMass, TransientSettings settings,
                 int substeps);
  void addObserver(StepObserver* o) override { observers_.push_back(o); }
  // Throws NumericalError when the state stops being finite.
  TransientSummary run(Vector& u, Vector& v, const Resume* resume = nullptr) override;
  void archive(StateArchive& a, const StateVectors& vectors) const override;
  int substeps() const { return substeps_; }

 private:
  // a = -M^-1 (F(u, vStar, t) + f_c(u, vStar)) with the status updated at u; with exactly
  // enforced contact, plus the contact accelerations that keep the next position, u + h vStar
  // + factor h^2 a, from penetrating (forward increments: factor 1/2 from an integer-step
  // velocity at the start, 1 from a half-step velocity).
  void acceleration(const Vector& u, const Vector& vStar, double t, double dt, Vector& a,
                    double h, double factor);
  void notify(const StepInfo& info);
  // The phases of run(): the initial state, and per nominal step its sub-steps and the check
  // that the state stayed finite (throws NumericalError naming the stability limit).
  void startState(const Vector& u, const Vector& v, StepInfo& info);
  void takeSubsteps(double target, double h);
  void requireFiniteState(long long n) const;

  ExplicitOperator& op_;
  RCP<const Vector> inverseMass_;
  TransientSettings s_;
  int substeps_ = 1;
  std::vector<StepObserver*> observers_;
  double t_ = 0.0;
  long long nominal_ = 0;
  TransientSummary sum_;
  RCP<Vector> u_, vHalf_, a_, v_, r_, uStar_;
};

}  // namespace choc
