#include "solvers/IterativeSolver.hpp"

#include <algorithm>
#include <cmath>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"
#include "core/Memory.hpp"
#include "solvers/ElasticityMultigrid.hpp"
#include "solvers/SymmetricOperator.hpp"

namespace choc {

namespace {

using RowMatrix = Tpetra::RowMatrix<double, LO, GO>;
using Preconditioner = Ifpack2::Preconditioner<double, LO, GO>;

class BelosSolver : public LinearSolver {
 public:
  BelosSolver(const Teuchos::ParameterList& p, std::shared_ptr<const NodalBlocks> blocks)
      : blocks_(std::move(blocks)),
        method_(p.get<std::string>("Method")),
        precType_(p.get<std::string>("Preconditioner")),
        tol_(p.get<double>("Tolerance")),
        maxIters_(p.get<int>("Maximum Iterations")),
        overlap_(p.isParameter("Schwarz Overlap") ? p.get<int>("Schwarz Overlap") : 1) {}

  void setMatrix(RCP<const CrsMatrix> A) override {
    A_ = A;
    prec_ = Teuchos::null;
    if (precType_ == "Multigrid") {
      if (multigrid_.is_null()) multigrid_ = rcp(new ElasticityMultigrid(blocks_));
      multigrid_->compute(A);
    } else if (precType_ != "None") {
      const std::string ifpackName =
          precType_ == "Jacobi" || precType_ == "Gauss-Seidel" ? "RELAXATION"
          : precType_ == "Additive Schwarz"                    ? "SCHWARZ"
                                                               : precType_;
      try {
        prec_ = Ifpack2::Factory::create<RowMatrix>(ifpackName, A);
        Teuchos::ParameterList pp;
        if (precType_ == "Jacobi") pp.set("relaxation: type", "Jacobi");
        if (precType_ == "Gauss-Seidel") pp.set("relaxation: type", "Symmetric Gauss-Seidel");
        if (precType_ == "RILUK") pp.set("fact: iluk level-of-fill", 1);
        if (precType_ == "Additive Schwarz") {
          // One subdomain per rank, overlapping by one layer of matrix neighbours, each
          // solved by ILU(0): a one-level domain decomposition (restricted additive Schwarz
          // would break the symmetry CG needs, so the combine mode stays "Add").
          pp.set("schwarz: overlap level", overlap_);
          pp.set("schwarz: combine mode", "Add");
          pp.set("inner preconditioner name", "RILUK");
          Teuchos::ParameterList inner;
          inner.set("fact: iluk level-of-fill", 0);
          pp.set("inner preconditioner parameters", inner);
        }
        prec_->setParameters(pp);
        prec_->initialize();
        prec_->compute();
      } catch (const std::exception& e) {
        rethrowIfOutOfMemory(describeFailure(e), "Ifpack2 " + precType_ + " preconditioner");
        throw NumericalError("Ifpack2 " + precType_ + " preconditioner failed: " +
                             std::string(e.what()).substr(0, 200));
      }
    }
    // The Belos problem and solver are built once per matrix and reused by every solve()
    // (only the right-hand side and the initial guess change between solves).
    problem_ = rcp(new Belos::LinearProblem<double, MultiVector, Operator>());
    problem_->setOperator(krylovOperator(A_));
    if (!prec_.is_null()) problem_->setRightPrec(prec_);
    if (!multigrid_.is_null()) problem_->setRightPrec(multigrid_);
    if (solver_.is_null()) {
      params_ = rcp(new Teuchos::ParameterList);
      params_->set("Convergence Tolerance", tol_);
      params_->set("Maximum Iterations", maxIters_);
      if (method_ == "GMRES") params_->set("Num Blocks", std::min(maxIters_, 300));
      Belos::SolverFactory<double, MultiVector, Operator> factory;
      solver_ = factory.create(method_ == "CG" ? "PSEUDOBLOCK CG"
                               : method_ == "MINRES" ? "MINRES" : "PSEUDOBLOCK GMRES", params_);
      activeTol_ = tol_;
    }
    solver_->setProblem(problem_);
    ++factorizations_;
  }

  LinearSolveStatus solve(const MultiVector& b, MultiVector& x) override {
    LinearSolveStatus st;
    if (!problem_->setProblem(Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b))) {
      st.message = "Belos could not set up the linear problem";
      return st;
    }
    const double tol = std::max(tol_, looser_);
    if (tol != activeTol_) {  // the whole list again: some managers reset what it leaves out
      params_->set("Convergence Tolerance", tol);
      solver_->setParameters(params_);
      activeTol_ = tol;
    }
    solver_->reset(Belos::Problem);
    Belos::ReturnType ret;
    try {
      ret = solver_->solve();
    } catch (const std::exception& e) {
      rethrowIfOutOfMemory(describeFailure(e), "Belos " + method_);
      st.message = "Belos " + method_ + " failed: " + std::string(e.what()).substr(0, 200);
      return st;
    }
    st.iterations = solver_->getNumIters();
    st.relativeResidual = relativeResidual(*A_, b, x);
    // Belos' own test is on the preconditioned residual: confirm with the true one.
    st.converged = ret == Belos::Converged && std::isfinite(st.relativeResidual) &&
                   st.relativeResidual <= 10.0 * tol;
    if (!st.converged)
      st.message = "Belos " + method_ + " did not converge in " + std::to_string(st.iterations) +
                   " iterations (true relative residual " + std::to_string(st.relativeResidual) + ")";
    return st;
  }

  std::string description() const override {
    return "Belos " + method_ + " + " + (multigrid_.is_null() ? precType_ : multigrid_->description());
  }

  // The operator the Krylov iterations multiply by: for the symmetric methods (CG, MINRES) on a
  // large symmetric A, A's products from half its entries (SymmetricOperator), refilled when a
  // new A keeps the graph; else A. The true residual check in solve() stays A's CRS product.
  RCP<const Operator> krylovOperator(const RCP<const CrsMatrix>& A) {
    if (method_ != "CG" && method_ != "MINRES") return A;
    if (symmetric_.is_null() || !symmetric_->refill(A)) {
      symmetric_ = Teuchos::null;  // the old copy's memory first
      symmetric_ = SymmetricOperator::build(A);
    }
    if (symmetric_.is_null()) return A;
    return symmetric_;
  }

 private:
  std::shared_ptr<const NodalBlocks> blocks_;
  std::string method_, precType_;
  double tol_, activeTol_ = 0.0;
  int maxIters_, overlap_;
  RCP<Teuchos::ParameterList> params_;
  RCP<const CrsMatrix> A_;
  RCP<SymmetricOperator> symmetric_;
  RCP<Preconditioner> prec_;
  RCP<ElasticityMultigrid> multigrid_;
  RCP<Belos::LinearProblem<double, MultiVector, Operator>> problem_;
  RCP<Belos::SolverManager<double, MultiVector, Operator>> solver_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeIterativeSolver(const Teuchos::ParameterList& params,
                                                  std::shared_ptr<const NodalBlocks> blocks) {
  if (params.get<std::string>("Preconditioner") == "Multigrid" && !blocks)
    throw InputError("Preconditioner 'Multigrid' needs the model's nodes; this analysis does not offer it "
                     "(valid here: None, RILUK, ILUT, Jacobi, Gauss-Seidel, Additive Schwarz)");
  return std::make_unique<BelosSolver>(params, std::move(blocks));
}

}  // namespace choc
