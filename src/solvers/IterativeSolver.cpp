#include "solvers/IterativeSolver.hpp"

#include <cmath>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "input/Errors.hpp"

namespace choc {

namespace {

using RowMatrix = Tpetra::RowMatrix<double, LO, GO>;
using Preconditioner = Ifpack2::Preconditioner<double, LO, GO>;

class BelosSolver : public LinearSolver {
 public:
  explicit BelosSolver(const Teuchos::ParameterList& p)
      : method_(p.get<std::string>("Method")),
        precType_(p.get<std::string>("Preconditioner")),
        tol_(p.get<double>("Tolerance")),
        maxIters_(p.get<int>("Maximum Iterations")) {}

  void setMatrix(RCP<const CrsMatrix> A) override {
    A_ = A;
    prec_ = Teuchos::null;
    if (precType_ != "None") {
      const std::string ifpackName =
          precType_ == "Jacobi" || precType_ == "Gauss-Seidel" ? "RELAXATION" : precType_;
      try {
        prec_ = Ifpack2::Factory::create<RowMatrix>(ifpackName, A);
        Teuchos::ParameterList pp;
        if (precType_ == "Jacobi") pp.set("relaxation: type", "Jacobi");
        if (precType_ == "Gauss-Seidel") pp.set("relaxation: type", "Symmetric Gauss-Seidel");
        if (precType_ == "RILUK") pp.set("fact: iluk level-of-fill", 1);
        prec_->setParameters(pp);
        prec_->initialize();
        prec_->compute();
      } catch (const std::exception& e) {
        throw NumericalError("Ifpack2 " + precType_ + " preconditioner failed: " +
                             std::string(e.what()).substr(0, 200));
      }
    }
    ++factorizations_;
  }

  LinearSolveStatus solve(const MultiVector& b, MultiVector& x) override {
    LinearSolveStatus st;
    auto problem = rcp(new Belos::LinearProblem<double, MultiVector, Operator>(
        A_, Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b)));
    if (!prec_.is_null()) problem->setRightPrec(prec_);
    if (!problem->setProblem()) {
      st.message = "Belos could not set up the linear problem";
      return st;
    }
    auto params = rcp(new Teuchos::ParameterList);
    params->set("Convergence Tolerance", tol_);
    params->set("Maximum Iterations", maxIters_);
    if (method_ == "GMRES") params->set("Num Blocks", std::min(maxIters_, 300));
    Belos::SolverFactory<double, MultiVector, Operator> factory;
    auto solver = factory.create(method_ == "CG" ? "PSEUDOBLOCK CG"
                                 : method_ == "MINRES" ? "MINRES" : "PSEUDOBLOCK GMRES", params);
    solver->setProblem(problem);
    Belos::ReturnType ret;
    try {
      ret = solver->solve();
    } catch (const std::exception& e) {
      st.message = "Belos " + method_ + " failed: " + std::string(e.what()).substr(0, 200);
      return st;
    }
    st.iterations = solver->getNumIters();
    st.relativeResidual = relativeResidual(*A_, b, x);
    // Belos' own test is on the preconditioned residual: confirm with the true one.
    st.converged = ret == Belos::Converged && std::isfinite(st.relativeResidual) &&
                   st.relativeResidual <= 10.0 * tol_;
    if (!st.converged)
      st.message = "Belos " + method_ + " did not converge in " + std::to_string(st.iterations) +
                   " iterations (true relative residual " + std::to_string(st.relativeResidual) + ")";
    return st;
  }

  std::string description() const override { return "Belos " + method_ + " + " + precType_; }

 private:
  std::string method_, precType_;
  double tol_;
  int maxIters_;
  RCP<const CrsMatrix> A_;
  RCP<Preconditioner> prec_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeIterativeSolver(const Teuchos::ParameterList& params) {
  return std::make_unique<BelosSolver>(params);
}

}  // namespace choc
