#include "physics/NewtonCorrection.hpp"

#include <stdexcept>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/TimerScope.hpp"

namespace choc {

NewtonCorrection::NewtonCorrection(std::unique_ptr<LinearSolver> solver, const MassDamping& mass,
                                   ContactStrategy* contact, DirectLinks* links, Teuchos::StackedTimer* timer)
    : solver_(std::move(solver)), mass_(mass), contact_(contact), links_(links), timer_(timer) {}

// The effective system at the first correction (an explicit run never builds it), and again
// when a slave node changed master face: a new graph (and factorisation).
void NewtonCorrection::build(const RCP<const CrsMatrix>& K) {
  if (system_ && contact_ && contact_->geometry().topologyVersion() != systemTopology_) {
    system_.reset();
    factored_.forget();
  }
  if (system_) return;
  systemTopology_ = contact_ ? contact_->geometry().topologyVersion() : 0;
  system_ = std::make_unique<EffectiveSystem>(K, mass_.matrix(), contact_,
                                              links_ ? links_->couplings() : std::vector<std::vector<GO>>());
  rhs_ = rcp(new MultiVector(system_->map(), 1));
  x_ = rcp(new MultiVector(system_->map(), 1));
  if (contact_ && contact_->projection() && !solver_->setProjection(contact_->projection()))
    throw std::logic_error("the linear solver cannot project out the contact multipliers (a direct solver)");
}

void NewtonCorrection::prepare(const RCP<const CrsMatrix>& K, long long tangent) {
  if (restoreKept_) restoreKeptFactorization(K, tangent);
  build(K);
}

int NewtonCorrection::unknowns(int fallback) const {
  return system_ ? int(system_->map()->getGlobalNumElements()) : fallback;
}

// The key of W = ca M + cv C + cd K_T with the given statuses, at the tangent's version.
FactorizationKey NewtonCorrection::keyOf(const EffectiveCoefficients& c, long long tangent,
                                         std::vector<char> status) const {
  FactorizationKey k;
  k.coefficients = {c.ca, c.cv, c.cd};
  k.tangent = tangent;
  k.status = std::move(status);
  return k;
}

// W filled and factored again when its key changed; true if it was.
bool NewtonCorrection::refactor(const EffectiveCoefficients& c, long long tangent) {
  std::vector<char> status = system_->statusKey();
  // The links' tangent, with v following u (dv/du = cv / cd); none for W = M.
  const bool linkTangent = links_ && c.cd > 0.0;
  if (linkTangent) {
    const std::vector<char> lk = links_->tangentKey();
    status.insert(status.end(), lk.begin(), lk.end());
  }
  FactorizationKey key = keyOf(c, tangent, std::move(status));
  const KeyChange change = factored_.compare(key);
  if (change == KeyChange::None) return false;
  {
    TimerScope ts(timer_, "Transient: assembly");
    if (key.tangent != filledTangent_) system_->stiffnessChanged();
    filledTangent_ = key.tangent;
    system_->fill(mass_.massCoefficient(c), mass_.stiffnessCoefficient(c),
                  linkTangent ? links_->tangent(c.cv / c.cd) : std::vector<MatrixEntry>());
  }
  TimerScope ts(timer_, "Transient: linear solve");
  // throws NumericalError when singular
  if (change == KeyChange::StatusOnly)
    solver_->updateMatrix(system_->matrix());  // a change of status: contact rows only
  else
    solver_->setMatrix(system_->matrix());
  factored_.record(std::move(key));
  return true;
}

CorrectionStatus NewtonCorrection::solve(const EffectiveCoefficients& c, long long tangent, const Vector& u,
                                         const Vector& r, Vector& du) {
  CorrectionStatus st;
  st.refactored = refactor(c, tangent);
  {
    TimerScope ts(timer_, "Transient: contact");
    system_->rightHandSide(r, u, *rhs_);
  }
  x_->putScalar(0.0);
  LinearSolveStatus ls;
  {
    TimerScope ts(timer_, "Transient: linear solve");
    solver_->relaxTolerance(nextLooser_);
    ls = solver_->solve(*rhs_, *x_);
    solver_->relaxTolerance(0.0);
    nextLooser_ = 0.0;
  }
  // A new factorisation (here or inside the solve) is of the current matrix: its entries are
  // what a checkpoint must rebuild it from while the solver may keep it.
  if (solver_->factorizations() != recordedFactorizations_ && solver_->mayKeepFactorization()) {
    kept_.factored = system_->lastEntries();
    kept_.coefficients = c;
    recordedFactorizations_ = solver_->factorizations();
  }
  st.ok = ls.converged;
  st.iterations = ls.iterations;
  st.message = ls.message;
  if (!st.ok) return st;
  TimerScope ts(timer_, "Transient: contact");
  system_->takeSolution(*x_, du);
  return st;
}

void NewtonCorrection::archive(StateArchive& a, const Comm& comm) const {
  if (!system_ || !factored_.valid() || !solver_->mayKeepFactorization()) return;
  KeptFactorization k = kept_;
  k.last = system_->lastEntries();
  k.keyStatus = factored_.key().status;
  k.solverState = solver_->keptState();
  k.archive(a, comm);
}

// The checkpoint's factored matrix, factored again, then its last filled matrix on the
// kept factorisation with the solver's state: the path of the run that wrote it.
void NewtonCorrection::restoreKeptFactorization(const RCP<const CrsMatrix>& K, long long tangent) {
  restoreKept_ = false;
  build(K);
  const EffectiveCoefficients& c = kept_.coefficients;
  const double aM = mass_.massCoefficient(c), aK = mass_.stiffnessCoefficient(c);
  TimerScope ts(timer_, "Transient: linear solve");
  system_->fillEntries(aM, aK, kept_.factored);  // rows another rank owns are skipped
  solver_->setMatrix(system_->matrix());
  kept_.factored = system_->lastEntries();
  recordedFactorizations_ = solver_->factorizations();
  system_->fillEntries(aM, aK, kept_.last);
  if (!kept_.solverState.empty() && kept_.solverState[0] != 0) solver_->updateMatrix(system_->matrix());
  solver_->restoreKeptState(kept_.solverState);
  factored_.record(keyOf(c, tangent, kept_.keyStatus));
}

}  // namespace choc
