#include "analysis/ModalAnalysis.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "input/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "output/ExodusResults.hpp"
#include "output/Log.hpp"
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
  declareChoice(p, "Direct Package", "KLU2", {"KLU2", "Basker", "SuperLU", "Umfpack"},
                "Amesos2 package factorising K - sigma M");
  declareBool(p, "Write Exodus", true, "write <name>.exo with one step per mode");
  return p;
}

namespace {

// A shift below every eigenvalue for 'Lowest' (K may be singular: free bodies).
double lowestShift(const CrsMatrix& K, const CrsMatrix& M) {
  const double ratio = K.getFrobeniusNorm() / M.getFrobeniusNorm();
  return -1e-4 * ratio;
}

}  // namespace

void ModalAnalysis::run(RunContext& ctx) {
  Model& model = ctx.model;
  auto K = model.stiffness();
  auto M = model.mass();
  EigenRequest req;
  req.numModes = params_.get<int>("Number of Modes");
  const long long n = model.dofs().numGlobal();
  const bool dense = params_.get<std::string>("Method") == "dense";
  if (!dense && req.numModes > n - 2)  // the Krylov-Schur basis needs two vectors more than the modes
    throwInput(inputFile_, path("Number of Modes"), std::to_string(req.numModes),
               "more modes than the model's " + std::to_string(n) + " unknowns allow",
               "ask for at most " + std::to_string(n - 2) + ", or use 'Method' = 'dense'");
  if (dense && req.numModes > n)
    throwInput(inputFile_, path("Number of Modes"), std::to_string(req.numModes),
               "more modes than the model's " + std::to_string(n) + " unknowns",
               "ask for at most " + std::to_string(n));
  const bool nearest = params_.get<std::string>("Which") == "Nearest Shift";
  const double fs = params_.get<double>("Shift Frequency");
  req.shift = nearest ? std::pow(2.0 * M_PI * fs, 2) : lowestShift(*K, *M);
  req.tolerance = params_.get<double>("Tolerance");
  req.maxRestarts = params_.get<int>("Maximum Restarts");
  req.directPackage = params_.get<std::string>("Direct Package");

  log() << "  " << n << " unknowns; " << req.numModes << " modes "
        << (nearest ? "nearest " + std::to_string(fs) + " Hz" : std::string("lowest")) << "\n";
  EigenResult res;
  try {
    res = dense ? solveDenseEigenproblem(K, M, req) : solveEigenproblem(K, M, req);
  } catch (const NumericalError& e) {  // name the analysis that failed
    throw NumericalError("modal analysis '" + name_ + "': " + e.what());
  }

  const double resTol = params_.get<double>("Residual Tolerance");
  if (dense)
    log() << "  dense LAPACK DSYGV on rank 0\n";
  else
    log() << "  Anasazi Block Krylov-Schur: " << res.restarts << " iterations, "
          << res.operatorApplies << " shift-invert solves\n";
  log() << "   mode   frequency [Hz]   gen. mass   residual\n";
  int worst = 0;
  for (int k = 0; k < req.numModes; ++k) {
    const double f = res.eigenvalues[k] > 0 ? std::sqrt(res.eigenvalues[k]) / (2 * M_PI) : 0.0;
    char line[128];
    std::snprintf(line, sizeof line, "  %5d  %15.6f  %10.6f  %9.2e\n", k + 1, f,
                  res.generalizedMass[k], res.residuals[k]);
    log() << line;
    if (!(res.residuals[k] <= res.residuals[worst])) worst = k;
  }
  if (!(res.residuals[worst] <= resTol)) {
    char msg[160];  // %g, not std::to_string: residuals are ~1e-12 and would print as 0.000000
    std::snprintf(msg, sizeof msg, " has residual %.3e above 'Residual Tolerance' %.3e",
                  res.residuals[worst], resTol);
    throw NumericalError("modal analysis '" + name_ + "': mode " + std::to_string(worst + 1) + msg);
  }

  // Outputs (rank 0 writes; every rank takes part in the gathers).
  const std::string base = ctx.outputDir + "/" + name_;
  std::vector<std::vector<double>> shapes;
  for (int k = 0; k < req.numModes; ++k) shapes.push_back(gatherAll(*res.vectors, k, model.dofs()));
  if (isRootRank()) {
    {
      const std::string csv = base + ".modes.csv";
      FILE* f = std::fopen((csv + ".part").c_str(), "w");
      if (!f) throw std::runtime_error("cannot write " + csv);
      std::fprintf(f, "mode,frequency_hz,generalized_mass,residual\n");
      for (int k = 0; k < req.numModes; ++k) {
        const double l = res.eigenvalues[k];
        std::fprintf(f, "%d,%.17g,%.17g,%.17g\n", k + 1, l > 0 ? std::sqrt(l) / (2 * M_PI) : 0.0,
                     res.generalizedMass[k], res.residuals[k]);
      }
      std::fclose(f);
      std::filesystem::rename(csv + ".part", csv);
    }
    if (params_.get<bool>("Write Exodus")) {
      ExodusResultsWriter exo(base + ".exo", model.mesh(), {"DISP_X", "DISP_Y", "DISP_Z"},
                              {"EIGENVALUE"});
      for (int k = 0; k < req.numModes; ++k) {
        const double l = res.eigenvalues[k];
        std::vector<std::vector<double>> nodal;
        for (int c : {DX, DY, DZ}) nodal.push_back(nodalComponent(shapes[k], model.dofs(), c));
        exo.writeStep(l > 0 ? std::sqrt(l) / (2 * M_PI) : 0.0, nodal, {l});
      }
      exo.finish();
    }
  }
  auto basis = std::make_shared<ModalBasis>();
  basis->name = name_;
  basis->eigenvalues = res.eigenvalues;
  basis->vectors = res.vectors;
  ctx.bases[name_] = basis;
}

}  // namespace choc
