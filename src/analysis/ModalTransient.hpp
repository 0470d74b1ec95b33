// Modal transient analysis: the generalized system of a modal basis computed earlier in the
// same input (diagonal modal mass and stiffness, modal damping, rigid-body modes undamped),
// initial fields projected on the basis, nonlinear shock links evaluated at their nodes,
// explicit integration with a critical-step check that includes the link stiffness.
#pragma once
#include <memory>

#include "analysis/Analysis.hpp"
#include "analysis/ModalStepView.hpp"
#include "checks/HistoryCheck.hpp"
#include "observers/TransientOutputs.hpp"
#include "physics/InitialConditions.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/StabilityPolicy.hpp"
#include "timeint/StepLoop.hpp"

namespace choc {

class ModalTransient : public Analysis {
 public:
  ModalTransient(const std::string& name, const Teuchos::ParameterList& params,
                 const std::string& inputFile);
  static Teuchos::ParameterList parameters();
  void setup(SetupContext& ctx) override;
  void run(RunContext& ctx) override;

 private:
  struct Settings {
    std::string basis, projection;
    StabilityCheck stability = StabilityCheck::Refuse;
    bool staticCorrection = false;
    double damping = 0, rigidFrequency = 0;
    std::vector<double> dampingList;  // empty: 'Modal Damping' for every mode
    double startTime = 0, endTime = 0, dt = 0;
    long long steps = 0;  // of the time grid
    ModalScheme scheme = ModalScheme::SymplecticEuler;
    int refinement = 1;
    TransientOutputSettings output;
  };
  struct Built {
    std::vector<ShockLink> links;
    std::vector<Probe> probes;
    std::vector<std::string> columns;
    std::vector<std::unique_ptr<HistoryCheck>> checks;
    InitialFields init;
  };
  // The diagonal generalized system of the basis.
  struct Generalized {
    std::vector<double> omega2, damping;
    int rigid = 0;
    double omega2Max = 0, xiMax = 0;
  };
  void readTimeGrid();
  Generalized generalizedSystem(const ModalBasis& basis) const;
  ModalState initialState(Model& model, const ModalBasis& basis, double residuals[2]) const;
  void summarize(RunSummary& s, const ModalBasis& basis, const Generalized& g, const ModalLinks& links,
                 int substeps, long long taken) const;
  int stepsPerStep(const Generalized& g, const ModalLinks& links) const;
  void describe(const Model& model, const ModalBasis& basis, const Generalized& g,
                const ModalLinks& links, const double residuals[2]) const;
  // What a checkpoint of the run adds to the integrator's records, and restores.
  struct ModalCheckpoint {
    ModalState& state;
    ModalLinks& links;
    const ModalBasis& basis;
    const CrsMatrix& mass;
  };
  void archiveState(const ModalCheckpoint& c, StateArchive& a, const StateVectors& vectors) const;
  void resumeState(const ModalCheckpoint& c, const StateArchive& a, const StateVectors& vectors) const;
  // The loop with its outputs; a run that stops writes its figures up to the last accepted state
  // into `stopped` (steps, time_reached, sub-steps, the history's energies) before rethrowing.
  void integrate(StepLoop& loop, ObserverSet& outputs, TransientView& view, const StateArchive* resume,
                 const StateVectors& vectors, const ModalIntegrator& integrator, RunSummary& stopped,
                 const HistoryObserver& history) const;

  const ModalBasis& basisFor(RunContext& ctx);

  Settings s_;
  std::unique_ptr<Built> b_;
  std::shared_ptr<const ModalBasis> basis_;
};

}  // namespace choc
