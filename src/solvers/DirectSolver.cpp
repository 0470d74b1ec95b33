#include "solvers/DirectSolver.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"
#include "core/DidYouMean.hpp"
#include "core/Memory.hpp"
#include "solvers/CapacitanceUpdate.hpp"
#include "solvers/FactorizationBackend.hpp"
#include "solvers/PreconditionedGmres.hpp"

namespace choc {

namespace {

// A factorisation (any backend) kept across solves, refined, and kept through changes of
// contact status while it pays.
class KeptDirectSolver : public LinearSolver {
 public:
  KeptDirectSolver(std::unique_ptr<FactorizationBackend> backend, double tol, int budget, bool capacitance)
      : backend_(std::move(backend)), tol_(tol), budget_(budget), capacitance_(capacitance) {}

  // The backend's failure is the same on every rank (none waits in the next solve).
  void setMatrix(RCP<const CrsMatrix> A) override {
    stale_ = false;
    spent_ = 0;
    A_ = A;
    const std::string failure = backend_->factor(A);
    if (!failure.empty()) reportFactorizationFailure(*A, failure);
    ++factorizations_;
    columns_.reset(A);  // the columns are P's; the rent is the scene's and carries on
    byCapacitance_ = false;
  }

  // An allocation failure is out of memory. KLU2 says only that its factorisation failed, for
  // a singular matrix as for its own allocations: when an allocation of the size of its
  // factors' first estimate (8 times the matrix's entries) fails now, it is memory.
  [[noreturn]] void reportFactorizationFailure(const CrsMatrix& A, const std::string& failure) {
    const std::string what = "direct solver " + backend_->name() + ": factorisation of " +
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
    prepared_ = false;
    byCapacitance_ = false;
  }

  bool mayKeepFactorization() const override { return !A_.is_null() && budget() > 0; }
  // stale_, spent_, counted_, prepared_, byCapacitance_, rent_, then the capacitance form's
  // blocks of columns (a checkpoint of a version before it has the first three).
  std::vector<long long> keptState() const override {
    std::vector<long long> s = {stale_, spent_, counted_, prepared_, byCapacitance_, rent_};
    const std::vector<long long> blocks = columns_.blocks();
    s.insert(s.end(), blocks.begin(), blocks.end());
    return s;
  }
  // After setMatrix() of the factored matrix and updateMatrix() of the last one (collective):
  // the same columns computed in the same blocks, and the last matrix prepared as it was.
  void restoreKeptState(const std::vector<long long>& s) override {
    if (s.size() < 3) return;
    stale_ = s[0] != 0;
    spent_ = int(s[1]);
    counted_ = s[2] != 0;
    if (s.size() < 6) return;
    std::string failure = columns_.restoreBlocks(A_->getRowMap(), s, 6, factoredSolve());
    size_t bought = 0;  // none: the blocks hold every column the last matrix needs
    if (failure.empty() && s[3] != 0 && s[4] != 0)
      prepared_ = byCapacitance_ = columns_.prepare(*A_, capacitanceColumns(), 0, factoredSolve(), failure, bought);
    else
      prepared_ = s[3] != 0;
    rent_ = s[5];
    if (!failure.empty()) throw NumericalError("restoring the kept factorisation: " + failure);
  }

  // x = A^-1 b for a matrix set by updateMatrix(): on the kept factorisation by its capacitance
  // form (exact, refined like a direct solve) when its columns fit, else by GMRES on it while it
  // pays (solveByUpdate()), else by a new factorisation.
  LinearSolveStatus solve(const MultiVector& b, MultiVector& x) override {
    if (stale_ && !prepared_ && capacitance_) {
      std::string failure = prepareCapacitance();
      if (!failure.empty()) return failedStatus(failure);
    }
    if (byCapacitance_) {
      LinearSolveStatus st = refinedSolve(b, x);
      if (st.converged) {
        countUpdate();
        return st;
      }
      byCapacitance_ = false;  // not within the tolerance: GMRES on the kept factorisation, or refactor
    }
    if (stale_ && spent_ < budget()) {
      LinearSolveStatus st = solveByUpdate(b, x);
      if (st.converged || !st.message.empty()) return st;
    }
    if (stale_) setMatrix(A_);  // the kept factorisation no longer pays: refactor
    return refinedSolve(b, x);
  }

  // x = A^-1 b by solveOnce(); then, while the residual is above the tolerance, up to
  // kRefinements steps of iterative refinement (x += A^-1 (b - A x)): a solve whose error
  // is only the factorisation's round-off amplified by the matrix's conditioning (stiff
  // contact and friction springs) is brought within the tolerance; a singular one is not.
  LinearSolveStatus refinedSolve(const MultiVector& b, MultiVector& x) {
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
    if (!failure.empty()) return failedStatus(failure);
    st.converged = std::isfinite(st.relativeResidual) && st.relativeResidual <= tol_;
    if (!st.converged && atRoundoffFloor(b, x, st.relativeResidual)) st.converged = true;
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

  std::string description() const override { return backend_->name(); }

 private:
  static constexpr int kRefinements = 2;

  // A refined solve whose residual refinement cannot lower: accepted when it is the round-off
  // of A x itself, ||r|| <= kFloorFactor eps || |A| |x| || (LU with partial pivoting is backward
  // stable: its residual is a modest multiple of that, 1,000 covering the growth of sparse
  // factors), and still at most kLargestAccepted of ||b||. An ill-conditioned but regular
  // matrix passes (a slender solid in bending: L / h = 100 leaves 5e-8 of ||b||, measured); a
  // singular one does not: its residual is of the size of b's part outside the range, or its x
  // is huge and inexact, far above 1e-4.
  static constexpr double kFloorFactor = 1000.0;
  static constexpr double kLargestAccepted = 1e-4;
  bool atRoundoffFloor(const MultiVector& b, const MultiVector& x, double relative) const {
    if (!std::isfinite(relative) || relative > kLargestAccepted) return false;
    return relative <= kFloorFactor * std::numeric_limits<double>::epsilon() * productTermsRatio(*A_, b, x);
  }

  // The extra preconditioned solves (beyond one per solve) a matrix may cost with a kept
  // factorisation before it is factored itself: the ratio of a factorisation's cost to one of
  // its solves. Refactoring once that much was spent on the current matrix is the rent-or-buy
  // rule: at most twice the cost of the better choice made in hindsight. Two estimates, the
  // larger taken:
  //  - by size, measured on the scale scene's slender HEX8 bars (KLU2: 40 at 43,308 unknowns, 94
  //    at 115,392: n^0.87), none below 5,000 unknowns;
  //  - by the factors' fill (entries per unknown, when the backend reports them) over 10: 15 for
  //    the bars at 9,664 unknowns (measured 16), 32 at 43,344 (29), 44 for a compact 3D block at
  //    4,869 (input/block_on_slab.xml: measured 80 to 88, a factorisation 0.39 s), where the
  //    dense separators of a compact mesh make factorisations dear at any size; counted from 20
  //    up (below, factorisations are cheap and refactoring keeps the solves direct).
  int budget() const {
    if (budget_ >= 0) return budget_;
    const double n = double(A_->getGlobalNumRows());
    const int bySize = n < 5000 ? 0 : int(40.0 * std::pow(n / 43308.0, 0.87));
    const int byFill = int(backend_->countedFactorEntries() / n / 10.0);
    return std::max(bySize, byFill >= kFillBudgetFrom ? byFill : 0);
  }
  static constexpr int kFillBudgetFrom = 20;

  // GMRES on the current matrix preconditioned by the kept factorisation, column by column,
  // within what is left of the budget. Not converged (and no failure message): refactor.
  // GMRES goes to a tenth of the Tolerance, or to the inexact Newton's relaxed tolerance
  // (relaxTolerance(), 'Newton/Linear Tolerance' = adaptive) when that is looser: an iterative
  // solve like any other. The oblique sphere (17,117 unknowns): 0.83 of the GMRES iterations,
  // the same Newton iterations.
  LinearSolveStatus solveByUpdate(const MultiVector& b, MultiVector& x) {
    LinearSolveStatus st;
    const double tolerance = std::max(tol_, looser_);
    auto precondition = [this](const Vector& v, Vector& z) { return solveOnce(v, z); };
    for (size_t j = 0; j < b.getNumVectors(); ++j) {
      auto bj = b.getVector(j);
      auto xj = x.getVectorNonConst(j);
      const GmresOutcome g = preconditionedGmres(*A_, precondition, *bj, *xj, std::max(0.1 * tol_, looser_),
                                                 std::max(1, budget() - spent_));
      spent_ += g.iterations;  // solves beyond a direct solve's one (x0 = P^-1 b, then one per iteration)
      rent_ += g.iterations;
      st.iterations += g.iterations;
      if (!g.failure.empty()) {
        st.message = "direct solve failed: " + g.failure;
        return st;
      }
      if (!g.converged) return st;
    }
    st.relativeResidual = relativeResidual(*A_, b, x);
    st.converged = st.relativeResidual <= tolerance;
    if (st.converged) countUpdate();
    return st;
  }

  // The capacitance form for A_, when its new columns are paid for: rent or buy again. New
  // columns (priced in solves: a backend solves columnsPerSolve() columns for the price of one)
  // are bought when they cost no more than a factorisation (budget(): GMRES failing would
  // refactor), or once the GMRES iterations spent on kept factorisations since the last
  // purchase (rent_, carried across factorisations) reach their cost; the rent is then spent.
  // The oblique sphere's contact zone grows node by node: each block is cheaper than a
  // factorisation and bought at once; the scale bars' 2 changed matrices at 115,392 unknowns (a
  // face of 256 rows at once, 42 GMRES iterations in all) never buy.
  std::string prepareCapacitance() {
    prepared_ = true;
    std::string failure;
    size_t bought = 0;
    const size_t perSolve = size_t(backend_->columnsPerSolve());
    const long long affordable = std::max<long long>(rent_, budget());
    byCapacitance_ = columns_.prepare(*A_, capacitanceColumns(), size_t(affordable) * perSolve, factoredSolve(),
                                      failure, bought);
    rent_ = std::max<long long>(0, rent_ - (long long)((bought + perSolve - 1) / perSolve));
    return failure;
  }

  // A matrix solved on the kept factorisation counts once.
  void countUpdate() {
    if (counted_) return;
    ++updates_;
    counted_ = true;
  }

  static LinearSolveStatus failedStatus(const std::string& failure) {
    LinearSolveStatus st;
    st.message = "direct solve failed: " + failure;
    return st;
  }

  // The capacitance form's columns may hold as many entries as the factors (an estimate of 8
  // times the matrix's when the backend does not say), so that they cost no more memory than the
  // factors and applying them no more than a solve; none when the budget is 0.
  size_t capacitanceColumns() const {
    if (!capacitance_ || budget() <= 0) return 0;
    double factors = backend_->factorEntries();
    if (!(factors > 0.0)) factors = 8.0 * double(A_->getGlobalNumEntries());
    return size_t(factors / double(A_->getGlobalNumRows()));
  }

  CapacitanceUpdate::FactoredSolve factoredSolve() {
    return [this](const MultiVector& b, MultiVector& x) { return backend_->solve(b, x); };
  }

  // A solve with the factorisation, through the capacitance form while A is not the factored matrix.
  std::string solveOnce(const MultiVector& b, MultiVector& x) {
    return byCapacitance_ ? columns_.solve(b, x, factoredSolve()) : backend_->solve(b, x);
  }

  std::unique_ptr<FactorizationBackend> backend_;
  double tol_;
  int budget_;          // extra solves a matrix may cost on a kept factorisation; -1: by size, budget()
  bool stale_ = false;  // A_ is not the factored matrix
  int spent_ = 0;       // extra preconditioned solves spent on the current matrix
  long long rent_ = 0;  // extra solves spent by GMRES on kept factorisations, not yet spent on columns
  bool counted_ = false;  // the current matrix was solved on the kept factorisation
  bool prepared_ = false;       // the capacitance form was tried for A_
  bool byCapacitance_ = false;  // A_ is solved by the capacitance form on the kept factorisation
  bool capacitance_;             // 'Update Form' = capacitance
  CapacitanceUpdate columns_;
  RCP<const CrsMatrix> A_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeDirectSolver(const std::string& package, double tol, int budget,
                                               bool symmetric, bool capacitance) {
  if (package == "MUMPS" && mumpsAvailable())
    return std::make_unique<KeptDirectSolver>(makeMumpsBackend(symmetric), tol, budget, capacitance);
  if (package == "MUMPS" || !amesos2Available(package))
    throw InputError("Linear Solver: direct package '" + package + "' is not available in this build; use " +
                     joinNames(directPackages()));
  return std::make_unique<KeptDirectSolver>(makeAmesos2RootBackend(package), tol, budget, capacitance);
}

}  // namespace choc
