#include "analysis/ModalAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "output/OutputDirectory.hpp"
#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "core/CollectiveFailure.hpp"
#include "core/Errors.hpp"
#include "physics/RigidBodies.hpp"
#include "core/Files.hpp"
#include "output/HistoryCsv.hpp"
#include "input/ParameterSpec.hpp"
#include "solvers/FactorizationBackend.hpp"
#include "output/ExodusResults.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "solvers/DenseEigenSolver.hpp"
#include "solvers/EigenSolver.hpp"

namespace choc {

Teuchos::ParameterList ModalAnalysis::parameters() {
  Teuchos::ParameterList p;
  declareRequiredChoice(p, "Type", {"Modal"}, "analysis type");
  declareInt(p, "Number of Modes", 10, "modes to compute", Range::atLeast(1));
  declareChoice(p, "Method", "Krylov-Schur", {"Krylov-Schur", "dense"},
                "Krylov-Schur: Anasazi on the shift-invert operator (at most n - 2 modes); "
                "dense: LAPACK DSYGV on rank 0 for small models (up to 4000 unknowns), which "
                "can return the complete basis");
  declareChoice(p, "Which", "Lowest", {"Lowest", "Nearest Shift"},
                "the lowest modes, or the modes whose eigenvalue omega^2 is nearest the shift");
  declareDouble(p, "Shift Frequency", 0.0,
                "shift f_s [Hz] for 'Nearest Shift': sigma = (2 pi f_s)^2", Range::nonNegative());
  declareDouble(p, "Tolerance", 1e-10, "Anasazi convergence tolerance", Range::positive());
  declareDouble(p, "Residual Tolerance", 1e-6,
                "largest accepted true residual ||K phi - lambda M phi|| / (||K phi|| + "
                "max(|lambda|,|sigma|) ||M phi||) of any mode",
                Range::positive());
  declareInt(p, "Maximum Restarts", 200, "Block Krylov-Schur restarts", Range::atLeast(0));
  declareChoice(p, "Direct Package", "KLU2", amesos2Packages(),
                "Amesos2 package factorising K - sigma M (the packages this build has)");
  declareBool(p, "Write Exodus", true, "write <name>.exo with one step per mode");
  return p;
}

namespace {

// A shift below every eigenvalue for 'Lowest' (K may be singular: free bodies).
double lowestShift(const CrsMatrix& K, const CrsMatrix& M) {
  const double ratio = K.getFrobeniusNorm() / M.getFrobeniusNorm();
  return -1e-4 * ratio;
}

// f = sqrt(lambda) / 2 pi, 0 for a rigid-body mode.
double frequencyOf(double lambda) { return lambda > 0 ? std::sqrt(lambda) / (2 * M_PI) : 0.0; }

}  // namespace

ModalAnalysis::ModalAnalysis(const std::string& name, const Teuchos::ParameterList& params,
                             const std::string& inputFile)
    : Analysis(name, params, inputFile) {
  s_.numModes = params_.get<int>("Number of Modes");
  s_.dense = params_.get<std::string>("Method") == "dense";
  s_.nearest = params_.get<std::string>("Which") == "Nearest Shift";
  s_.shiftFrequency = params_.get<double>("Shift Frequency");
  s_.tolerance = params_.get<double>("Tolerance");
  s_.residualTolerance = params_.get<double>("Residual Tolerance");
  s_.maxRestarts = params_.get<int>("Maximum Restarts");
  s_.directPackage = params_.get<std::string>("Direct Package");
  s_.writeExodus = params_.get<bool>("Write Exodus");
}

void ModalAnalysis::setup(SetupContext& ctx) {
  refuseRigidBlocks(ctx.model, "Analyses/" + name_, "a modal analysis");
  const long long n = ctx.model.dofs().numGlobal();
  if (!s_.dense && s_.numModes > n - 2)  // the Krylov-Schur basis needs two vectors more than the modes
    throwInput(inputFile_, path("Number of Modes"), std::to_string(s_.numModes),
               "more modes than the model's " + std::to_string(n) + " unknowns allow",
               "ask for at most " + std::to_string(n - 2) + ", or use 'Method' = 'dense'");
  if (s_.dense && s_.numModes > n)
    throwInput(inputFile_, path("Number of Modes"), std::to_string(s_.numModes),
               "more modes than the model's " + std::to_string(n) + " unknowns",
               "ask for at most " + std::to_string(n));
  ctx.modalAnalyses[name_] = s_.numModes;
}

void ModalAnalysis::run(RunContext& ctx) {
  const EigenResult res = solve(ctx.model);
  logModes(res);
  RunSummary& summary = ctx.summary;
  summary.set("modes", s_.numModes);
  summary.set("method", s_.dense ? "dense LAPACK" : "Anasazi Block Krylov-Schur");
  summary.set("iterations", res.restarts);
  summary.set("shift_invert_solves", res.operatorApplies);
  std::vector<double> hz;
  for (double l : res.eigenvalues) hz.push_back(frequencyOf(l));
  summary.set("frequencies_hz", hz);
  summary.set("largest_residual", *std::max_element(res.residuals.begin(), res.residuals.end()));
  checkResiduals(res);
  writeResults(ctx, res);
  auto basis = std::make_shared<ModalBasis>();
  basis->name = name_;
  basis->eigenvalues = res.eigenvalues;
  basis->vectors = res.vectors;
  ctx.bases[name_] = basis;
}

EigenResult ModalAnalysis::solve(Model& model) const {
  auto K = model.stiffness();
  auto M = model.mass();
  EigenRequest req;
  req.numModes = s_.numModes;
  req.shift = s_.nearest ? std::pow(2.0 * M_PI * s_.shiftFrequency, 2) : lowestShift(*K, *M);
  req.tolerance = s_.tolerance;
  req.maxRestarts = s_.maxRestarts;
  req.directPackage = s_.directPackage;
  log() << "  " << model.dofs().numGlobal() << " unknowns; " << req.numModes << " modes "
        << (s_.nearest ? "nearest " + std::to_string(s_.shiftFrequency) + " Hz" : std::string("lowest"))
        << "\n";
  EigenResult res;
  try {
    res = s_.dense ? solveDenseEigenproblem(K, M, req) : solveEigenproblem(K, M, req);
  } catch (const NumericalError& e) {  // name the analysis that failed
    throw NumericalError("modal analysis '" + name_ + "': " + e.what());
  }
  if (s_.dense)
    log() << "  dense LAPACK DSYGV on rank 0\n";
  else
    log() << "  Anasazi Block Krylov-Schur: " << res.restarts << " iterations, "
          << res.operatorApplies << " shift-invert solves\n";
  return res;
}

void ModalAnalysis::logModes(const EigenResult& res) const {
  log() << "   mode   frequency [Hz]   gen. mass   residual\n";
  for (int k = 0; k < s_.numModes; ++k)
    log() << format("  %5d  %15.6f  %10.6f  %9.2e\n", k + 1, frequencyOf(res.eigenvalues[k]),
                    res.generalizedMass[k], res.residuals[k]);
}

void ModalAnalysis::checkResiduals(const EigenResult& res) const {
  int worst = 0;
  for (int k = 0; k < s_.numModes; ++k)
    if (!(res.residuals[k] <= res.residuals[worst])) worst = k;
  // %g, not std::to_string: residuals are ~1e-12 and would print as 0.000000
  if (!(res.residuals[worst] <= s_.residualTolerance))
    throw NumericalError(format("modal analysis '%s': mode %d has residual %.3e above 'Residual Tolerance' %.3e",
                                name_.c_str(), worst + 1, res.residuals[worst], s_.residualTolerance));
}

// <name>.modes.csv and <name>.exo (rank 0 writes; every rank takes part in the gathers and
// learns of a failure to write).
void ModalAnalysis::writeResults(const RunContext& ctx, const EigenResult& res) const {
  const Model& model = ctx.model;
  std::vector<std::vector<double>> shapes;
  for (int k = 0; k < s_.numModes; ++k) shapes.push_back(gatherAll(*res.vectors, k, model.dofs()));
  std::string failure;
  if (isRootRank()) {
    try {
      writeFiles(ctx.outputDir + "/" + name_, model, res, shapes);
    } catch (const OutputError& e) {
      failure = e.what();
    }
  }
  failure = collectiveFailure(*model.comm(), failure);
  if (!failure.empty()) throw OutputError("modal analysis '" + name_ + "': " + failure);
}

void ModalAnalysis::writeFiles(const std::string& base, const Model& model, const EigenResult& res,
                               const std::vector<std::vector<double>>& shapes) const {
  std::string text = "mode,frequency_hz,generalized_mass,residual\n";
  for (int k = 0; k < s_.numModes; ++k)
    text += format("%d,%.17g,%.17g,%.17g\n", k + 1, frequencyOf(res.eigenvalues[k]),
                   res.generalizedMass[k], res.residuals[k]);
  const std::string csv = base + suffix::modes;
  writeWholeFile(csv, text, true, incompletePath(csv));
  if (!s_.writeExodus) return;
  const std::vector<int> comps = spatialComponents(model.mesh().dimension);
  std::vector<std::string> names;
  for (int c : comps) names.push_back(std::string("DISP_") + "XYZ"[c]);
  ExodusResultsWriter exo(base + suffix::exodus, model.mesh(), names, {"EIGENVALUE"});
  for (int k = 0; k < s_.numModes; ++k) {
    std::vector<std::vector<double>> nodal;
    for (int c : comps) nodal.push_back(nodalComponent(shapes[k], model.dofs(), c));
    exo.writeStep(frequencyOf(res.eigenvalues[k]), nodal, {res.eigenvalues[k]});
  }
  exo.finish();
}

}  // namespace choc
