// Direct implicit transient analysis (Type "Transient"): Newmark family (average
// acceleration, modified average acceleration, HHT, generalized-alpha, Newmark) over the
// model's K and M with Rayleigh damping, constant nodal forces and contact (Lagrange,
// penalty or the continuous augmented Lagrangian). Writes <name>.history.csv (probes,
// energies, per-pair force and gap) and <name>.exo (every 'Exodus Interval' steps), checks
// the declared rows and compares with the exact solution; prints Newton iterations,
// refactorisations and the time split (assembly, linear solve, contact, output).
#pragma once
#include "analysis/Analysis.hpp"

namespace choc {

class ImplicitTransient : public Analysis {
 public:
  using Analysis::Analysis;
  static Teuchos::ParameterList parameters();
  void run(RunContext& ctx) override;

  // Figures of the last run (for tests and the benchmark).
  struct Figures {
    int steps = 0, newtonIterations = 0, refactorizations = 0, activeSetIterations = 0;
    int maxNewtonPerStep = 0, failedSteps = 0, unknowns = 0;
    double wall = 0, assembly = 0, linearSolve = 0, contact = 0, output = 0;
  };
  const Figures& figures() const { return figures_; }

 private:
  Figures figures_;
};

}  // namespace choc
