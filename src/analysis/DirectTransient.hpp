// Direct implicit transient analysis (Type "Transient"): Newmark family (average
// acceleration, modified average acceleration, HHT, generalized-alpha, Newmark) over the
// model's K and M with Rayleigh damping, constant nodal forces and contact (Lagrange,
// penalty or the continuous augmented Lagrangian). Writes <name>.history.csv (probes,
// energies, per-pair force and gap) and <name>.exo (every 'Exodus Interval' steps), evaluates
// its checks; prints Newton iterations, refactorisations and the time split (assembly,
// linear solve, contact, output).
#pragma once
#include <chrono>
#include <memory>

#include <Teuchos_StackedTimer.hpp>

#include "analysis/Analysis.hpp"
#include "analysis/ExplicitPlan.hpp"
#include "checks/HistoryCheck.hpp"
#include "contact/ContactParameters.hpp"
#include "contact/ContactStrategies.hpp"
#include "observers/Probes.hpp"
#include "observers/TransientOutputs.hpp"
#include "observers/TransientReport.hpp"
#include "physics/InitialConditions.hpp"
#include "physics/MasslessBasis.hpp"
#include "physics/CriticalStep.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/StructuralOperator.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/StabilityPolicy.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/NewmarkFamily.hpp"
#include "timeint/StructuralStepper.hpp"

namespace choc {

class RigidBodies;

class DirectStepView;

class DirectTransient : public Analysis {
 public:
  DirectTransient(const std::string& name, const Teuchos::ParameterList& params,
                    const std::string& inputFile);
  static Teuchos::ParameterList parameters();
  void setup(SetupContext& ctx) override;
  void run(RunContext& ctx) override;

  // Figures of the last run (for tests and the benchmark).
  using Figures = TransientFigures;
  const Figures& figures() const { return figures_; }

 private:
  struct Settings {
    NewmarkFamily scheme = NewmarkFamily::averageAcceleration();
    bool explicitScheme = false;  // 'central differences': CentralDifferenceStepper, lumped mass
    StabilityCheck stability = StabilityCheck::Refuse;
    int criticalStepInterval = 100;  // steps between estimates on the deformed mesh (finite strain)
    TransientSettings time;
    double rayleighK = 0, rayleighM = 0;
    ContactSettings contact;
    TransientOutputSettings output;
  };
  // What setup builds for the run.
  struct Built {
    RCP<const CrsMatrix> K, M;
    RCP<const CrsMatrix> meshMass;  // the mesh's lumped mass (M before any redistribution)
    bool finiteStrain = false;      // some block has 'Strain' = 'finite'
    std::string solverChoice;  // the 'auto' linear solver's reason, for the log
    std::string massPackage;   // a direct linear solver's package: the velocity update's M^-1 by it
    std::shared_ptr<const Loads> loads;
    std::unique_ptr<ContactManager> contact;
    std::unique_ptr<ContactStrategy> strategy;  // how the run enforces contact (over contact)
    std::unique_ptr<DirectLinks> links;  // null: no shock links
    long long masslessNodes = 0;
    std::string massFallback;  // why Contact Mass = auto kept the standard mass (empty: it did not)
    std::string massChoice;    // what 'auto' chose when it is not the redistributed mass (empty)
    MasslessBasis massless;    // 'Contact Mass' = normal: the rotation onto the normals
    std::unique_ptr<LinearSolver> solver;
    std::vector<Probe> probes;
    std::vector<std::string> columns;
    std::vector<std::unique_ptr<HistoryCheck>> checks;
    InitialFields init;
    std::unique_ptr<ExplicitPlan> explicitPlan;  // central differences only
    std::shared_ptr<RigidBodies> rigid;  // rigid blocks (central differences only); null: none
    RCP<const Vector> nodalMass;         // with rigid bodies: the lumped diagonal without their rows
  };
  void readScheme();
  void readTimeSettings();
  void buildContact(Model& model);
  void buildNormalMass(const Model& model);
  void buildSolver(const Model& model);
  void setupExplicit(const Model& model);
  std::shared_ptr<InternalForce> internalForce(Model& model) const;
  std::unique_ptr<StructuralStepper> stepper(StructuralOperator& op) const;
  void reportRun(RunContext& ctx, const TransientSummary& sum, TransientReport& report,
                 Teuchos::StackedTimer& timer, std::chrono::steady_clock::time_point start,
                 const HistoryObserver& history);
  TransientFacts facts() const;
  void configure(StructuralOperator& op, Model& model) const;
  static void continueView(DirectStepView& view, const StateArchive& resume, const StateVectors& vectors,
                           const Model& model);

  Settings s_;
  std::unique_ptr<Built> b_;
  Figures figures_;
};

}  // namespace choc
