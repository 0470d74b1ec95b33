// What every analysis of an input shares: the model, the output directory, the modal bases
// computed so far, and the checks collected for checks.csv.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "analysis/Model.hpp"
#include "output/Checks.hpp"

namespace choc {

struct ModalBasis {
  std::string name;
  std::vector<double> eigenvalues;  // omega^2, ascending
  RCP<const MultiVector> vectors;   // M-normalised mode shapes on the model's map
  double frequencyHz(int mode) const;
};

struct RunContext {
  Model& model;
  std::string outputDir;
  std::map<std::string, std::shared_ptr<const ModalBasis>> bases;
  std::vector<CheckResult> checks;
  bool failedChecks() const;
};

class Analysis {
 public:
  Analysis(std::string name, const Teuchos::ParameterList& params, std::string inputFile)
      : name_(std::move(name)), params_(params), inputFile_(std::move(inputFile)) {}
  virtual ~Analysis() = default;
  const std::string& name() const { return name_; }
  // Runs to completion, or throws InputError / NumericalError (outputs then abandoned).
  virtual void run(RunContext& ctx) = 0;

 protected:
  std::string path(const std::string& key) const { return "Analyses/" + name_ + "/" + key; }
  std::string name_;
  Teuchos::ParameterList params_;  // validated, with defaults
  std::string inputFile_;
};

}  // namespace choc
