// The one step loop of every transient (Tempus' integrator/stepper split): the loop walks the
// nominal time grid (timeint/TimeGrid.hpp), starts from the initial state or a checkpoint,
// counts steps, tells the observers of every accepted state and writes the loop's part of a
// checkpoint; a Stepper is one scheme's way from an accepted state to the next:
//   - NewmarkStepper (timeint/NewmarkStepper.hpp): the implicit Newmark family, Newton and
//     the active set per step, dt cut on failure (the step control);
//   - CentralDifferenceStepper (timeint/CentralDifferenceStepper.hpp): explicit central
//     differences on a lumped mass, sub-steps from the stability policy;
//   - ModalStepper (timeint/ModalStepper.hpp): the modal integrators on a basis' generalised
//     system.
// A stepper's accepted states are reported through its own observers (it knows its state:
// physical vectors, or modal coordinates); the loop decides when.
#pragma once
#include <string>

#include "restart/StateArchive.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/NewtonActiveSet.hpp"
#include "timeint/TimeGrid.hpp"

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

struct TransientSummary {
  int steps = 0;
  int newtonIterations = 0;
  int activeSetIterations = 0;
  int refactorizations = 0;  // counted by the operator's solves (effective matrix changes)
  int krylovIterations = 0;
  int failedSteps = 0;       // attempts that were cut
  int backtracks = 0;        // Newton corrections halved because they inverted an element
  int maxNewtonPerStep = 0;
  double smallestStep = 0.0;
  long long substeps = 0;  // explicit: the sub-steps taken in all (the deformed mesh's may vary)
  int maxSubsteps = 0;     // explicit: the most in one step
};

// The nominal step a stepper is asked to take: number n of the grid, from the accepted state
// at t to target; dt the grid's step, length the step's own (dt, or the last one cut).
struct NominalStep {
  long long n = 0;
  double t = 0, target = 0, dt = 0, length = 0;
};

// A step controller's state inside one nominal step (the loop resets it at each): the length
// of the next attempt and the cuts made so far.
struct StepControl {
  double h = 0;
  int cuts = 0;
};

// One accepted state: the time it reached (the nominal step's target when the step is
// complete), the length taken, the sub-step's length (explicit schemes; 0 otherwise) and the
// Newton outcome (implicit schemes).
struct Advance {
  double time = 0, dt = 0, substep = 0;
  NewtonOutcome newton;
};

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Completes the initial state at t0 (the initial acceleration, the constraints' statuses);
  // firstStep: the first nominal step's length. Sets what the initial StepInfo reports of the
  // scheme (info.substep) and the summary's starting figures.
  virtual void start(double t0, double firstStep, TransientSummary& sum, StepInfo& info) = 0;
  // The next accepted state from s.t toward s.target: the whole nominal step, or an accepted
  // part of it when the stepper cuts dt (c carries the cut length and count). Counts its work
  // (Newton iterations, failed attempts) into sum. Throws NumericalError when it cannot go on.
  virtual Advance advance(const NominalStep& s, StepControl& c, TransientSummary& sum) = 0;
  // Shows the accepted state to the stepper's observers (info: the loop's account of it).
  virtual void notify(const StepInfo& info) = 0;
  // The stepper's state in a checkpoint, and back (its own records; the loop writes
  // "driver/time", "driver/nominal" and "driver/summary").
  virtual void archiveState(StateArchive& a, const StateVectors& vectors) const = 0;
  virtual void restoreState(const StateArchive& a, const StateVectors& vectors) = 0;
};

class StepLoop {
 public:
  // Where a checkpoint's state is.
  struct Resume {
    const StateArchive& archive;
    const StateVectors& vectors;
  };
  StepLoop(Stepper& stepper, TimeGrid grid) : stepper_(stepper), grid_(grid) {}
  // Integrates from the stepper's initial state at the grid's start to its end. With
  // `resume`, continues from the state a checkpoint holds (archive()) and does not report the
  // checkpoint's state again.
  TransientSummary run(const Resume* resume = nullptr);
  // The accepted state and counters (call from an observer at a nominal boundary): "driver/*"
  // and the stepper's records.
  void archive(StateArchive& a, const StateVectors& vectors) const;
  const TimeGrid& grid() const { return grid_; }
  // The counters and the time of the last accepted state so far (what a run that stops reports).
  const TransientSummary& progress() const { return sum_; }
  double time() const { return t_; }

 private:
  void startState(StepInfo& info);
  void resumeState(const Resume& r);
  void nominalStep(long long n, StepInfo& info);

  Stepper& stepper_;
  TimeGrid grid_;
  double t_ = 0.0;         // time of the accepted state
  long long nominal_ = 0;  // nominal steps completed
  TransientSummary sum_;
};

}  // namespace choc
