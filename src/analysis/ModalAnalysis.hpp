// Modal analysis: the N modes nearest a shift (or the N lowest) by Anasazi, each checked by
// its true residual; writes <name>.exo (one step per mode, time = frequency in Hz) and
// <name>.modes.csv, and keeps the basis for modal transient analyses of the same input.
#pragma once
#include "analysis/Analysis.hpp"
#include "solvers/EigenSolver.hpp"

namespace choc {

class ModalAnalysis : public Analysis {
 public:
  ModalAnalysis(const std::string& name, const Teuchos::ParameterList& params,
                const std::string& inputFile);
  static Teuchos::ParameterList parameters();
  void setup(SetupContext& ctx) override;
  void run(RunContext& ctx) override;

 private:
  struct Settings {
    int numModes = 0;
    bool dense = false, nearest = false, writeExodus = true;
    double shiftFrequency = 0, tolerance = 0, residualTolerance = 0;
    int maxRestarts = 0;
    std::string directPackage;
  };
  EigenResult solve(Model& model) const;
  void logModes(const EigenResult& res) const;
  void checkResiduals(const EigenResult& res) const;
  void writeResults(const RunContext& ctx, const EigenResult& res) const;
  void writeFiles(const std::string& base, const Model& model, const EigenResult& res,
                  const std::vector<std::vector<double>>& shapes) const;
  Settings s_;
};

}  // namespace choc
