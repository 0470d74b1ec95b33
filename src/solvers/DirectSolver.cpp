#include "solvers/DirectSolver.hpp"

#include <cmath>
#include <cstdio>

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"
#include "core/CollectiveFailure.hpp"
#include "core/Memory.hpp"
#include "solvers/PreconditionedGmres.hpp"

namespace choc {

namespace {

std::string firstLine(const std::string& s) {
  auto p = s.find('\n');
  return p == std::string::npos ? s : s.substr(0, p);
}

// Amesos2 on a matrix whose communicator is MPI_COMM_SELF. (Debian's Trilinos 13.2 KLU2
// returns wrong solutions whenever the communicator has more than one rank, even with every
// row on rank 0 — see tests/unit/test_solvers_mpi_direct.cpp — so choc gathers the system to
// rank 0 itself and factors it there, which is what Amesos2 does internally for KLU2.)
class SerialFactorization {
 public:
  explicit SerialFactorization(std::string package) : package_(std::move(package)) {}
  void factor(RCP<const CrsMatrix> A) {
    if (solver_.is_null() || A.get() != A_.get()) {
      solver_ = Amesos2::create<CrsMatrix, MultiVector>(package_, A);
      solver_->symbolicFactorization();
    }
    A_ = A;
    solver_->numericFactorization();
  }
  void solve(const MultiVector& b, MultiVector& x) {
    solver_->solve(Teuchos::ptr(&x), Teuchos::ptr(&b));
  }
  RCP<const CrsMatrix> matrix() const { return A_; }

 private:
  std::string package_;
  RCP<const CrsMatrix> A_;
  RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver_;
};

class Amesos2Solver : public LinearSolver {
 public:
  Amesos2Solver(std::string package, double tol, int budget)
      : package_(package), tol_(tol), budget_(budget), serial_(package) {}

  // On more than one rank only rank 0 factors: its failure is shared (CollectiveFailure.hpp)
  // so that every rank throws, none waits in the next solve.
  void setMatrix(RCP<const CrsMatrix> A) override {
    stale_ = false;
    spent_ = 0;
    std::string failure;
    try {
      A_ = A;
      if (A->getComm()->getSize() == 1) {
        serial_.factor(A);
      } else {
        gatherToRoot(*A);
        if (A->getComm()->getRank() == 0) serial_.factor(rootSerial_);
      }
    } catch (const std::exception& e) {
      failure = describeFailure(e);
    }
    failure = collectiveFailure(*A->getComm(), failure);
    if (!failure.empty()) reportFactorizationFailure(*A, failure);
    ++factorizations_;
  }

  // An allocation failure is out of memory. KLU2 says only that its factorisation failed, for
  // a singular matrix as for its own allocations: when an allocation of the size of its
  // factors' first estimate (8 times the matrix's entries) fails now, it is memory.
  [[noreturn]] void reportFactorizationFailure(const CrsMatrix& A, const std::string& failure) {
    const std::string what = "direct solver " + package_ + ": factorisation of " +
                             std::to_string(A.getGlobalNumRows()) + " unknowns";
    rethrowIfOutOfMemory(failure, what);
    const double factors = 8.0 * double(A.getGlobalNumEntries()) * (sizeof(double) + sizeof(int));
    if (!canAllocate(static_cast<std::size_t>(factors)))
      throw OutOfMemory(what + " failed, and " + byteSize(factors) + " (an estimate of its factors) "
                        "cannot be allocated now; run on a machine with more memory, or with an "
                        "iterative 'Linear Solver/Method'");
    throw NumericalError(what + " failed (singular or unconstrained system?): " + failure);
  }

  // Keeps the factorisation: solve() decides whether it still pays (see solveByUpdate()).
  void updateMatrix(RCP<const CrsMatrix> A) override {
    if (A_.is_null() || A->getGlobalNumRows() != A_->getGlobalNumRows() || budget() == 0) {
      setMatrix(A);
      return;
    }
    A_ = A;
    stale_ = true;
    spent_ = 0;
    counted_ = false;
  }

  bool mayKeepFactorization() const override { return !A_.is_null() && budget() > 0; }
  std::vector<long long> keptState() const override { return {stale_, spent_, counted_}; }
  void restoreKeptState(const std::vector<long long>& s) override {
    if (s.size() != 3) return;
    stale_ = s[0] != 0;
    spent_ = int(s[1]);
    counted_ = s[2] != 0;
  }

  // x = A^-1 b by the factorisation (by GMRES on the kept one while it pays, see
  // solveByUpdate()); then, while the residual is above the tolerance, up to
  // kRefinements steps of iterative refinement (x += A^-1 (b - A x)): a solve whose error
  // is only the factorisation's round-off amplified by the matrix's conditioning (stiff
  // contact and friction springs) is brought within the tolerance; a singular one is not.
  LinearSolveStatus solve(const MultiVector& b, MultiVector& x) override {
    if (stale_ && spent_ < budget()) {
      LinearSolveStatus st = solveByUpdate(b, x);
      if (st.converged || !st.message.empty()) return st;
    }
    if (stale_) setMatrix(A_);  // the kept factorisation no longer pays: refactor
    LinearSolveStatus st;
    std::string failure = solveOnce(b, x);
    st.relativeResidual = failure.empty() ? relativeResidual(*A_, b, x) : NAN;
    for (int k = 0; failure.empty() && k < kRefinements && st.relativeResidual > tol_; ++k) {
      MultiVector r(b, Teuchos::Copy), d(x.getMap(), x.getNumVectors());
      A_->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
      failure = solveOnce(r, d);
      if (!failure.empty()) break;
      x.update(1.0, d, 1.0);
      st.relativeResidual = relativeResidual(*A_, b, x);
    }
    if (!failure.empty()) {
      st.message = "direct solve failed: " + failure;
      return st;
    }
    st.converged = std::isfinite(st.relativeResidual) && st.relativeResidual <= tol_;
    if (!st.converged) {
      char message[160];
      std::snprintf(message, sizeof message,
                    "direct solve residual %.3e above %.3e after %d refinements (singular or "
                    "ill-conditioned matrix)",
                    st.relativeResidual, tol_, kRefinements);
      st.message = message;
    }
    return st;
  }

  std::string description() const override { return "Amesos2 " + package_; }

 private:
  static constexpr int kRefinements = 2;

  // The extra preconditioned solves (beyond one per solve) a matrix may cost with a kept
  // factorisation before it is factored itself: the ratio of a KLU2 factorisation's cost to
  // one of its solves, measured on the scale scene's HEX8 bars (40 at 43,308 unknowns, 94 at
  // 115,392: n^0.87). Refactoring once that much was spent on the current matrix is the
  // rent-or-buy rule: at most twice the cost of the better choice made in hindsight. None
  // below 5,000 unknowns (factorisations are cheap there).
  int budget() const {
    if (budget_ >= 0) return budget_;
    const double n = double(A_->getGlobalNumRows());
    return n < 5000 ? 0 : int(40.0 * std::pow(n / 43308.0, 0.87));
  }

  // GMRES on the current matrix preconditioned by the kept factorisation, column by column,
  // within what is left of the budget. Not converged (and no failure message): refactor.
  LinearSolveStatus solveByUpdate(const MultiVector& b, MultiVector& x) {
    LinearSolveStatus st;
    auto precondition = [this](const Vector& v, Vector& z) { return solveOnce(v, z); };
    for (size_t j = 0; j < b.getNumVectors(); ++j) {
      auto bj = b.getVector(j);
      auto xj = x.getVectorNonConst(j);
      const GmresOutcome g = preconditionedGmres(*A_, precondition, *bj, *xj, 0.1 * tol_,
                                                 std::max(1, budget() - spent_ - 1));
      spent_ += g.iterations > 0 ? g.iterations + 1 : 0;  // solves beyond a direct solve's one
      st.iterations += g.iterations;
      if (!g.failure.empty()) {
        st.message = "direct solve failed: " + g.failure;
        return st;
      }
      if (!g.converged) return st;
    }
    st.relativeResidual = relativeResidual(*A_, b, x);
    st.converged = st.relativeResidual <= tol_;
    if (st.converged && !counted_) {
      ++updates_;
      counted_ = true;
    }
    return st;
  }

  // One solve with the factorisation (gathered to rank 0 on several ranks); the failure's
  // first line, or "".
  std::string solveOnce(const MultiVector& b, MultiVector& x) {
    std::string failure;
    if (A_->getComm()->getSize() == 1) {
      try {
        serial_.solve(b, x);
      } catch (const std::exception& e) {
        failure = describeFailure(e);
      }
      rethrowIfOutOfMemory(failure, "direct solver " + package_ + ": solve");
      return failure;
    }
    MultiVector bRoot(rootMap_, b.getNumVectors()), xRoot(rootMap_, b.getNumVectors());
    bRoot.doImport(b, *importer_, Tpetra::INSERT);
    if (A_->getComm()->getRank() == 0) {
      try {
        MultiVector bs(serialMap_, b.getNumVectors()), xs(serialMap_, b.getNumVectors());
        copyLocal(bRoot, bs);
        serial_.solve(bs, xs);
        copyLocal(xs, xRoot);
      } catch (const std::exception& e) {
        failure = describeFailure(e);
      }
    }
    x.doExport(xRoot, *importer_, Tpetra::INSERT);
    failure = collectiveFailure(*A_->getComm(), failure);
    rethrowIfOutOfMemory(failure, "direct solver " + package_ + ": solve");
    return failure;
  }

  static void copyLocal(const MultiVector& from, MultiVector& to) {
    for (size_t j = 0; j < from.getNumVectors(); ++j) {
      auto src = from.getData(j);
      auto dst = to.getDataNonConst(j);
      for (size_t i = 0; i < from.getLocalLength(); ++i) dst[i] = src[i];
    }
  }

  // Copies A to rank 0, then into a matrix on MPI_COMM_SELF there.
  void gatherToRoot(const CrsMatrix& A) {
    auto comm = A.getComm();
    const Tpetra::global_size_t n = A.getGlobalNumRows();
    if (rootMap_.is_null() || rootMap_->getGlobalNumElements() != n) {
      rootMap_ = rcp(new Map(n, comm->getRank() == 0 ? size_t(n) : 0, 0, comm));
      importer_ = rcp(new Tpetra::Import<LO, GO>(A.getRowMap(), rootMap_));
      RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
      if (comm->getRank() == 0) serialMap_ = rcp(new Map(n, size_t(n), 0, self));
    }
    CrsMatrix root(rootMap_, 0);
    root.doImport(A, *importer_, Tpetra::INSERT);
    root.fillComplete(rootMap_, rootMap_);
    if (comm->getRank() != 0) return;
    std::vector<size_t> counts(n);
    for (size_t i = 0; i < n; ++i) counts[i] = root.getNumEntriesInGlobalRow(GO(i));
    auto S = rcp(new CrsMatrix(serialMap_, Teuchos::ArrayView<const size_t>(counts)));
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    for (size_t i = 0; i < n; ++i) {
      cols.resize(counts[i]);
      vals.resize(counts[i]);
      size_t got = 0;
      root.getGlobalRowCopy(GO(i), cols(), vals(), got);
      S->insertGlobalValues(GO(i), cols(0, got), vals(0, got));
    }
    S->fillComplete(serialMap_, serialMap_);
    rootSerial_ = S;
  }

  std::string package_;
  double tol_;
  int budget_;          // extra solves a matrix may cost on a kept factorisation; -1: by size, budget()
  bool stale_ = false;  // A_ is not the factored matrix
  int spent_ = 0;       // extra preconditioned solves spent on the current matrix
  bool counted_ = false;  // the current matrix was solved on the kept factorisation
  SerialFactorization serial_;
  RCP<const CrsMatrix> A_;
  RCP<const Map> rootMap_, serialMap_;
  RCP<Tpetra::Import<LO, GO>> importer_;
  RCP<const CrsMatrix> rootSerial_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeDirectSolver(const std::string& package, double tol, int budget) {
  if (!Amesos2::query(package))
    throw InputError("Linear Solver: direct package '" + package +
                     "' is not available in this Trilinos build; use KLU2");
  return std::make_unique<Amesos2Solver>(package, tol, budget);
}

}  // namespace choc
