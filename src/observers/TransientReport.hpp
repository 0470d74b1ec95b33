// What a direct transient tells of its run: at the start, the run's description (unknowns,
// scheme, critical step, solver, contact mass, contact, links); at the end, the figures recorded
// from the step loop's summary, the operator and the timers, logged and written to
// <name>.summary.json (a run that stopped writes the counts it reached too).
#pragma once
#include <chrono>
#include <string>

#include <Teuchos_StackedTimer.hpp>

#include "output/RunSummary.hpp"
#include "physics/CriticalStep.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/Model.hpp"
#include "physics/StructuralOperator.hpp"
#include "timeint/StepLoop.hpp"

namespace choc {

// What the analysis knows of its run, for the report.
struct TransientFacts {
  bool explicitScheme = false;
  std::string schemeName, schemeDescription;
  double timeStep = 0, startTime = 0, endTime = 0, rayleighK = 0, rayleighM = 0;
  std::string solverChoice;  // the 'auto' linear solver's reason ("" when chosen by the input)
  // Central differences: the plan at the start.
  int substeps = 1;
  double criticalStep = 0;
  FrequencyBound bound;
  std::string stabilityWarning;
  // Contact: its method, a given stick stiffness, the contact mass's nodes made massless and why
  // 'auto' kept the standard mass ("" when it did not).
  std::string contactMethod;
  bool givenTangentialStiffness = false;
  long long masslessNodes = 0;
  std::string massFallback;
  std::string massChoice;  // what 'auto' chose, and its trade ("": not auto)
};

// Figures of the last run (for tests and the benchmark).
struct TransientFigures {
  int steps = 0, newtonIterations = 0, refactorizations = 0, activeSetIterations = 0;
  int keptFactorizations = 0;  // changes of contact status solved on the previous factorisation
  int maxNewtonPerStep = 0, failedSteps = 0, unknowns = 0;
  double wall = 0, assembly = 0, linearSolve = 0, contact = 0, output = 0;
};

class TransientReport {
 public:
  TransientReport(TransientFacts facts, const StructuralOperator& op, const ContactManager* contact,
                  const DirectLinks* links)
      : f_(std::move(facts)), op_(op), contact_(contact), links_(links) {}
  // The run's description on the log; runMass is the run's M (the contact mass's change shown).
  void describe(Model& model, const CrsMatrix& runMass) const;
  void record(const TransientSummary& sum, const Teuchos::StackedTimer& timer,
              std::chrono::steady_clock::time_point start);
  void logFigures(const TransientSummary& sum, const Model& model, Teuchos::StackedTimer& timer) const;
  // The counts (no collective call: a run that stopped writes them too), then the timers' min and
  // max over the ranks (collective).
  void summarizeCounts(RunSummary& s, const TransientSummary& sum, double timeReached) const;
  void summarize(RunSummary& s, const TransientSummary& sum, const Comm& comm) const;
  const TransientFigures& figures() const { return figures_; }

 private:
  TransientFacts f_;
  const StructuralOperator& op_;
  const ContactManager* contact_;
  const DirectLinks* links_;
  TransientFigures figures_;
};

}  // namespace choc
