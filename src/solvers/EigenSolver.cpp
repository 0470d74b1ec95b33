#include "solvers/EigenSolver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "fem/MatrixOps.hpp"
#include "core/Errors.hpp"
#include "core/Memory.hpp"
#include "solvers/DirectSolver.hpp"

namespace choc {

namespace {

// Y = (K - sigma M)^-1 M X
class ShiftInvertOperator : public Operator {
 public:
  ShiftInvertOperator(RCP<const CrsMatrix> M, std::unique_ptr<LinearSolver> solver)
      : M_(std::move(M)), solver_(std::move(solver)) {}
  RCP<const Map> getDomainMap() const override { return M_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return M_->getRangeMap(); }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override {
    MultiVector MX(M_->getRangeMap(), X.getNumVectors());
    M_->apply(X, MX);
    MultiVector Z(Y.getMap(), Y.getNumVectors());
    LinearSolveStatus st = solver_->solve(MX, Z);
    ++applies_;
    if (!st.converged) throw NumericalError("shift-invert solve failed: " + st.message);
    Y.update(alpha, Z, beta);
  }
  int applies() const { return applies_; }

 private:
  RCP<const CrsMatrix> M_;
  std::unique_ptr<LinearSolver> solver_;
  mutable int applies_ = 0;
};

// A deterministic start vector: depends on the global index only, not on the rank count.
void fillStart(MultiVector& X) {
  auto map = X.getMap();
  for (size_t j = 0; j < X.getNumVectors(); ++j) {
    auto col = X.getDataNonConst(j);
    for (size_t i = 0; i < X.getLocalLength(); ++i) {
      const double g = static_cast<double>(map->getGlobalElement(i));
      col[i] = 1.0 + 0.5 * std::sin(12.9898 * g + 78.233 * (j + 1));
    }
  }
}

using Eigenproblem = Anasazi::BasicEigenproblem<double, MultiVector, Operator>;
using KrylovSchur = Anasazi::BlockKrylovSchurSolMgr<double, MultiVector, Operator>;

// Block Krylov-Schur needs Num Blocks > numModes and Num Blocks <= n - 1 (krylovSchurParameters).
void requirePossibleModeCount(int numModes, long long n) {
  if (numModes < 1 || numModes > n - 2)
    throw InputError("Modal analysis: 'Number of Modes' = " + std::to_string(numModes) +
                     " must be between 1 and " + std::to_string(n - 2) + " (the model has " +
                     std::to_string(n) + " unknowns)");
}

// The Hermitian problem of the shift-invert operator with M's inner product, from the
// deterministic start vector.
RCP<Eigenproblem> makeEigenproblem(RCP<const Operator> op, RCP<const CrsMatrix> M, RCP<const Map> domain,
                                   int numModes) {
  auto X0 = rcp(new MultiVector(domain, 1));
  fillStart(*X0);
  auto problem = rcp(new Eigenproblem(op, M, X0));
  problem->setHermitian(true);
  problem->setNEV(numModes);
  if (!problem->setProblem()) throw NumericalError("Anasazi: eigenproblem set-up failed");
  return problem;
}

// The solver's parameters for n unknowns.
Teuchos::ParameterList krylovSchurParameters(const EigenRequest& req, long long n) {
  Teuchos::ParameterList pl;
  pl.set("Which", std::string("LM"));
  pl.set("Block Size", 1);
  // The Krylov basis holds Num Blocks + 1 vectors: at most n - 1 blocks for n unknowns (Anasazi
  // throws "Orthogonalization constraints not feasible" when the basis reaches n + 1 vectors).
  const int numBlocks = static_cast<int>(std::min<long long>(n - 1, std::max(2 * req.numModes, req.numModes + 20)));
  pl.set("Num Blocks", numBlocks);
  pl.set("Maximum Restarts", req.maxRestarts);
  pl.set("Convergence Tolerance", req.tolerance);
  pl.set("Verbosity", static_cast<int>(Anasazi::Errors));
  return pl;
}

// Anasazi's own exceptions become a NumericalError (or the out-of-memory error).
Anasazi::ReturnType runKrylovSchur(KrylovSchur& mgr) {
  try {
    return mgr.solve();
  } catch (const NumericalError&) {
    throw;
  } catch (const std::exception& e) {
    rethrowIfOutOfMemory(describeFailure(e), "Anasazi Block Krylov-Schur");
    throw NumericalError(std::string("Anasazi Block Krylov-Schur failed: ") +
                         std::string(e.what()).substr(0, 200));
  }
}

void requireConverged(Anasazi::ReturnType ret, int converged, int iterations, const EigenRequest& req) {
  if (ret != Anasazi::Converged || converged < req.numModes)
    throw NumericalError("Anasazi Block Krylov-Schur converged " + std::to_string(converged) +
                         " of " + std::to_string(req.numModes) + " modes in " +
                         std::to_string(iterations) + " iterations with 'Maximum Restarts' = " +
                         std::to_string(req.maxRestarts) + "; raise 'Maximum Restarts' or loosen 'Tolerance'");
}

// The requested modes of the solution nearest the shift, by increasing eigenvalue.
EigenResult lowestModes(const Anasazi::Eigensolution<double, MultiVector>& sol, const EigenRequest& req,
                        RCP<const Map> domain) {
  // theta = 1/(lambda - sigma)  =>  lambda = sigma + 1/theta
  std::vector<double> lambda(sol.numVecs);
  for (int i = 0; i < sol.numVecs; ++i) lambda[i] = req.shift + 1.0 / sol.Evals[i].realpart;
  std::vector<int> order(sol.numVecs);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda[a] < lambda[b]; });
  order.resize(req.numModes);

  EigenResult res;
  res.vectors = rcp(new MultiVector(domain, req.numModes));
  for (int k = 0; k < req.numModes; ++k) {
    res.vectors->getVectorNonConst(k)->assign(*sol.Evecs->getVector(order[k]));
    res.eigenvalues.push_back(lambda[order[k]]);
  }
  return res;
}

}  // namespace

void finishEigenResult(const CrsMatrix& K, const CrsMatrix& M, double shift, EigenResult& res) {
  MultiVector Kphi(K.getRangeMap(), 1), Mphi(M.getRangeMap(), 1), r(K.getRangeMap(), 1);
  res.generalizedMass.clear();
  res.residuals.clear();
  for (size_t k = 0; k < res.vectors->getNumVectors(); ++k) {
    auto phi = res.vectors->getVectorNonConst(k);
    M.apply(*phi, Mphi);
    std::vector<double> gm(1);
    phi->dot(*Mphi.getVector(0), Teuchos::ArrayView<double>(gm));
    if (!(gm[0] > 0)) throw NumericalError("modal analysis: mode with non-positive generalized mass");
    phi->scale(1.0 / std::sqrt(gm[0]));
    M.apply(*phi, Mphi);
    K.apply(*phi, Kphi);
    const double lambda = res.eigenvalues[k];
    r.assign(Kphi);
    r.update(-lambda, Mphi, 1.0);
    std::vector<double> nr(1), nk(1), nm(1), g(1);
    r.norm2(Teuchos::ArrayView<double>(nr));
    Kphi.norm2(Teuchos::ArrayView<double>(nk));
    Mphi.norm2(Teuchos::ArrayView<double>(nm));
    phi->dot(*Mphi.getVector(0), Teuchos::ArrayView<double>(g));
    res.generalizedMass.push_back(g[0]);
    res.residuals.push_back(nr[0] / (nk[0] + std::max(std::abs(lambda), std::abs(shift)) * nm[0]));
  }
}

EigenResult solveEigenproblem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M,
                              const EigenRequest& req) {
  const long long n = static_cast<long long>(K->getGlobalNumRows());
  requirePossibleModeCount(req.numModes, n);
  RCP<CrsMatrix> A = addMatrices(1.0, *K, -req.shift, *M);
  auto solver = makeDirectSolver(req.directPackage, 1e-8);
  solver->setMatrix(A);
  auto op = rcp(new ShiftInvertOperator(M, std::move(solver)));

  RCP<Eigenproblem> problem = makeEigenproblem(op, M, K->getDomainMap(), req.numModes);
  Teuchos::ParameterList pl = krylovSchurParameters(req, n);
  KrylovSchur mgr(problem, pl);
  const Anasazi::ReturnType ret = runKrylovSchur(mgr);
  const auto& sol = problem->getSolution();
  requireConverged(ret, sol.numVecs, mgr.getNumIters(), req);

  EigenResult res = lowestModes(sol, req, K->getDomainMap());
  finishEigenResult(*K, *M, req.shift, res);
  res.restarts = mgr.getNumIters();
  res.operatorApplies = op->applies();
  return res;
}

}  // namespace choc
