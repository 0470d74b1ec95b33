// The step loop of a Newmark-family integration over a SecondOrderOperator: initial
// acceleration from equilibrium, one Newton/active-set solve per step, step hooks for
// output and energies, and the step controller: a failed step (Newton or active set) is
// retried with dt cut by 'cutFactor' up to 'maxCuts' times inside the nominal step, then the
// run stops with a NumericalError naming the time and the reason. A step that did not
// converge is never passed to the observers.
#pragma once
#include <string>
#include <vector>

#include "restart/StateArchive.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/NewmarkFamily.hpp"
#include "timeint/NewtonActiveSet.hpp"

namespace choc {

struct TransientSettings {
  double startTime = 0.0;
  double endTime = 0.0;
  double timeStep = 0.0;
  int maxCuts = 0;         // cuts of dt allowed inside one nominal step
  double cutFactor = 0.5;  // dt <- cutFactor * dt on failure
  NewtonSettings newton;
  std::string label = "transient";  // for messages
};

struct StepInfo {
  int step = 0;           // accepted steps so far (0: the initial state)
  double time = 0.0;
  double dt = 0.0;        // 0 for the initial state
  NewtonOutcome newton;   // of this step
  int cuts = 0;           // dt cuts made inside the current nominal step
  bool last = false;      // the final step of the run
  bool boundary = true;   // the end of a nominal step (not a sub-step of a cut one)
  long long nominal = 0;  // nominal steps completed
  double substep = 0.0;   // explicit schemes: the length of the step's last sub-step (0: implicit)
};

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

struct TransientSummary {
  int steps = 0;
  int newtonIterations = 0;
  int activeSetIterations = 0;
  int refactorizations = 0;  // counted by the operator's solves (effective matrix changes)
  int krylovIterations = 0;
  int failedSteps = 0;       // attempts that were cut
  int maxNewtonPerStep = 0;
  double smallestStep = 0.0;
};

// What a transient analysis drives: a step loop (implicit Newmark family or explicit central
// differences) with observers and checkpoints.
class StepLoop {
 public:
  virtual ~StepLoop() = default;
  virtual void addObserver(StepObserver* o) = 0;
  // Where a checkpoint's state is.
  struct Resume {
    const StateArchive& archive;
    const StateVectors& vectors;
  };
  // Integrates from (u, v) at startTime to endTime; u and v hold the final state on return.
  // With `resume`, continues from the state a checkpoint holds (archive()), with the
  // operator's own state restored, and does not report the checkpoint's state again.
  virtual TransientSummary run(Vector& u, Vector& v, const Resume* resume = nullptr) = 0;
  // The accepted state and counters (call from a step observer at a nominal boundary):
  // records "driver/*" and the operator's.
  virtual void archive(StateArchive& a, const StateVectors& vectors) const = 0;

 protected:
  // The accepted state (u, v, a at time t after `nominal` nominal steps) and the counters, as
  // "driver/*" with the operator's own state, and back (the operator's state restored and
  // saved as the accepted one).
  struct State {
    Vector &u, &v, &a;
    double& time;
    long long& nominal;
    TransientSummary& summary;
  };
  struct ConstState {
    const Vector &u, &v, &a;
    double time;
    long long nominal;
    const TransientSummary& summary;
  };
  static void putState(StateArchive& a, const StateVectors& vectors, const ConstState& s,
                       const SecondOrderOperator& op);
  static void getState(const Resume& r, const State& s, SecondOrderOperator& op);
};

class TransientDriver : public StepLoop {
 public:
  TransientDriver(SecondOrderOperator& op, NewmarkFamily scheme, TransientSettings settings);
  void addObserver(StepObserver* o) override { observers_.push_back(o); }
  // Throws NumericalError when a step fails beyond the allowed cuts.
  TransientSummary run(Vector& u, Vector& v, const Resume* resume = nullptr) override;
  void archive(StateArchive& a, const StateVectors& vectors) const override;
  const NewmarkFamily& scheme() const { return scheme_; }

 private:
  // One attempt from state n to t + dt; returns the outcome, leaves u1, v1, a1.
  NewtonOutcome attempt(double t, double dt);
  void initialState(TransientSummary& sum);
  void notify(const StepInfo& info);
  // The phases of run(): the starting state, then each nominal step by attempts (rejected and
  // cut, or accepted).
  void startState(const Vector& u, const Vector& v, const Resume* resume);
  void nominalStep(long long n, long long nominal, double& t, StepInfo& info);
  void countIterations(const NewtonOutcome& out);
  void rejectAttempt(double t, double h, int cuts, const NewtonOutcome& out);
  void acceptAttempt(double t);

  SecondOrderOperator& op_;
  NewmarkFamily scheme_;
  TransientSettings s_;
  std::vector<StepObserver*> observers_;
  double t_ = 0.0;          // time of the accepted state
  long long nominal_ = 0;   // nominal steps completed
  TransientSummary sum_;
  // State at t_n and its weighted terms, and the trial state at t_{n+1}.
  RCP<Vector> u0_, v0_, a0_, Ma0_, F0_, Ma1_, F1_, u1_, v1_, a1_;
  RCP<Vector> uTilde_, vTilde_, inertia_, forces_, fc_, change_;
};

}  // namespace choc
