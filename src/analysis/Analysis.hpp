// One analysis of an input, in three phases:
//   settings  the constructor reads the validated parameter list once into typed settings
//             (and refuses what needs no model: a step longer than the run, a scheme out of
//             range...);
//   setup     resolves every reference on the model (node and side sets, probes, the modal
//             basis named, contact pairs, solver and method compatibility, checks) and
//             builds what the run needs, with no time stepping and no file written;
//             `choc check` stops here, so it reports every reference error `choc run` would;
//   run       a short sequence of named steps, writing the results.
#pragma once
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "observers/CheckpointObserver.hpp"
#include "output/Checks.hpp"
#include "output/RunSummary.hpp"
#include "physics/ModalBasis.hpp"
#include "physics/Model.hpp"

namespace choc {

// What setup sees: the model, and the modal analyses set up before this one (whose bases
// the run will have computed).
struct SetupContext {
  Model& model;
  std::map<std::string, int> modalAnalyses;  // name -> number of modes
};

// What run sees: the model, the output directory, the bases computed so far, the checks.
struct RunContext {
  Model& model;
  std::string outputDir;
  std::map<std::string, std::shared_ptr<const ModalBasis>> bases;
  std::vector<CheckResult> checks;
  const Teuchos::ParameterList* input = nullptr;  // the whole validated input (run identity)
  std::shared_ptr<const StateArchive> restart;    // a checkpoint to continue (--restart)
  RunSummary summary;  // what the running analysis did (<analysis>.summary.json)
  bool failedChecks() const;
};

class Analysis {
 public:
  Analysis(std::string name, const Teuchos::ParameterList& params, std::string inputFile)
      : name_(std::move(name)), params_(params), inputFile_(std::move(inputFile)) {}
  virtual ~Analysis() = default;
  const std::string& name() const { return name_; }
  // Throws InputError for a reference the model cannot resolve.
  virtual void setup(SetupContext& ctx) = 0;
  // Runs to completion, or throws NumericalError / Interrupted (outputs then abandoned).
  virtual void run(RunContext& ctx) = 0;

 protected:
  std::string path(const std::string& key) const { return "Analyses/" + name_ + "/" + key; }
  // The checkpoint to continue when this analysis wrote it (else null).
  const StateArchive* resumeFor(const RunContext& ctx) const;
  // Where this analysis's checkpoints go and the identity they carry (no state yet).
  CheckpointPlan checkpointPlan(const RunContext& ctx) const;
  std::string name_;
  Teuchos::ParameterList params_;  // validated, with defaults
  std::string inputFile_;
};

}  // namespace choc
