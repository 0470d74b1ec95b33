#include "solvers/LinearSolver.hpp"

#include <cmath>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "input/ParameterSpec.hpp"
#include "solvers/DirectSolver.hpp"
#include "solvers/FactorizationBackend.hpp"
#include "solvers/IterativeSolver.hpp"

namespace choc {

Teuchos::ParameterList linearSolverParameters() {
  Teuchos::ParameterList p;
  declareChoice(p, "Method", "auto", {"auto", "Direct", "CG", "GMRES", "MINRES"},
                "Direct: Amesos2 sparse LU; CG/GMRES/MINRES: Belos Krylov solvers; auto (transient; "
                "it also picks the preconditioner): Direct up to 5,000 unknowns (1,000 with finite-strain "
                "blocks, a new tangent at each Newton iteration) or when the matrix "
                "is not symmetric positive definite (Continuous contact multipliers between meshed "
                "bodies, friction, links; multipliers against rigid obstacles alone are condensed out "
                "of an iterative solve, src/contact/ContactCondensation.hpp, Lagrange's between meshed "
                "bodies projected out, src/contact/ContactProjection.hpp, and with friction "
                "GMRES + Jacobi is chosen when mass-dominated); else CG "
                "+ Jacobi when the Newton matrix is mass-dominated (largest row ratio of stiffness "
                "to mass <= 100), Direct up to 100,000 unknowns, beyond CG + Jacobi up to a ratio "
                "of 10,000 and CG + Multigrid above; the log states the choice "
                "(src/solvers/SolverChoice.hpp)");
  declareChoice(p, "Direct Package", "KLU2", directPackages(),
                "sparse direct solver of Method = Direct (the packages this build has): KLU2 and "
                "the other Amesos2 packages factor the system gathered on rank 0; MUMPS factors it "
                "on every rank (distributed rows, its own ordering), see "
                "src/solvers/FactorizationBackend.hpp");
  declareInt(p, "Update Budget", -1,
             "Method = Direct: after a change of contact status alone (same time step and "
             "coefficients) the factorisation is kept, and a changed matrix that 'Update Form' "
             "does not solve is solved by GMRES preconditioned by it (a low-rank update) until "
             "that matrix has cost this many extra preconditioned solves, then it is factored "
             "itself; 0 always refactors (no update of either form); -1 (auto): the cost of a "
             "factorisation in solves, the larger of two estimates: by size (none below 5,000 "
             "unknowns, 40 at 43,308, 93 at 115,392: slender bars, measured) and by the factors' "
             "entries per unknown over 10 when the package reports them and that gives 20 or "
             "more (a compact 3D mesh: 44 for input/block_on_slab.xml at 4,869 unknowns)",
             Range::atLeast(-1));
  declareChoice(p, "Update Form", "capacitance", {"capacitance", "GMRES"},
                "Method = Direct, a kept factorisation (Update Budget): 'capacitance' solves a "
                "matrix that differs from the factored one in a few rows exactly, by one solve "
                "with the factorisation and a dense matrix of the changed rows (the "
                "Sherman-Morrison-Woodbury form; each changed row's column of the inverse is "
                "computed once and kept with the factorisation, at most as many columns as the "
                "factors hold entries per unknown, then it refactors), GMRES when it does not "
                "apply; 'GMRES': GMRES alone (src/solvers/CapacitanceUpdate.hpp)");
  declareChoice(p, "Preconditioner", "RILUK",
                {"None", "RILUK", "ILUT", "Jacobi", "Gauss-Seidel", "Additive Schwarz", "Multigrid"},
                "preconditioner of the Krylov methods: Ifpack2's (RILUK, ILUT and Gauss-Seidel act "
                "on each rank's rows; Additive Schwarz: one overlapping subdomain per rank, "
                "ILU(0) inside) or Multigrid: MueLu smoothed aggregation for elasticity (whole "
                "nodes aggregated, the rigid-body modes as near-null space, Chebyshev smoothing; "
                "transient analyses; src/solvers/ElasticityMultigrid.hpp)");
  declareInt(p, "Schwarz Overlap", 1, "overlap level of 'Additive Schwarz' (0: block Jacobi)",
             Range::atLeast(0));
  declareDouble(p, "Tolerance", 1e-10,
                "relative residual ||b-Ax||/||b|| a solve must reach (checked on the true "
                "residual, also for the direct solver)",
                Range::positive());
  declareInt(p, "Maximum Iterations", 1000, "Krylov iterations before a solve fails",
             Range::atLeast(1));
  return p;
}

std::unique_ptr<LinearSolver> makeLinearSolver(const Teuchos::ParameterList& params, bool symmetric,
                                               std::shared_ptr<const NodalBlocks> blocks) {
  const std::string method = params.get<std::string>("Method");
  if (method == "Direct" || method == "auto")  // 'auto' unresolved (no regime known): Direct
    return makeDirectSolver(params.get<std::string>("Direct Package"),
                            std::max(params.get<double>("Tolerance"), 1e-8),
                            params.get<int>("Update Budget"), symmetric,
                            params.get<std::string>("Update Form") == "capacitance");
  return makeIterativeSolver(params, std::move(blocks));
}

double relativeResidual(const CrsMatrix& A, const MultiVector& b, const MultiVector& x) {
  MultiVector r(b, Teuchos::Copy);
  A.apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  const size_t nv = b.getNumVectors();
  std::vector<double> nr(nv), nb(nv);
  r.norm2(Teuchos::ArrayView<double>(nr));
  b.norm2(Teuchos::ArrayView<double>(nb));
  double worst = 0.0;
  for (size_t i = 0; i < nv; ++i) {
    const double rel = nb[i] > 0 ? nr[i] / nb[i] : nr[i];
    if (!(rel <= worst)) worst = rel;  // NaN propagates
  }
  return worst;
}

double productTermsRatio(const CrsMatrix& A, const MultiVector& b, const MultiVector& x) {
  const size_t nv = b.getNumVectors();
  MultiVector onCols(A.getColMap(), nv);
  const auto importer = A.getGraph()->getImporter();
  if (importer.is_null())
    onCols.assign(x);
  else
    onCols.doImport(x, *importer, Tpetra::INSERT);
  const auto L = A.getLocalMatrixHost();
  const size_t rows = size_t(L.graph.row_map.extent(0)) - 1;
  std::vector<double> local(nv, 0.0), global(nv, 0.0), nb(nv);
  for (size_t j = 0; j < nv; ++j) {
    auto xc = onCols.getData(j);
    for (size_t i = 0; i < rows; ++i) {
      double t = 0.0;
      for (auto k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k)
        t += std::abs(L.values(k)) * std::abs(xc[L.graph.entries(k)]);
      local[j] += t * t;
    }
  }
  Teuchos::reduceAll<int, double>(*A.getComm(), Teuchos::REDUCE_SUM, int(nv), local.data(), global.data());
  b.norm2(Teuchos::ArrayView<double>(nb));
  double worst = 0.0;
  for (size_t j = 0; j < nv; ++j) {
    const double ratio = nb[j] > 0 ? std::sqrt(global[j]) / nb[j] : 0.0;
    if (!(ratio <= worst)) worst = ratio;
  }
  return worst;
}

}  // namespace choc
