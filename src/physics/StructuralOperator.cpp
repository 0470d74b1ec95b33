#include "physics/StructuralOperator.hpp"

#include "physics/MasslessInitialAcceleration.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

StructuralOperator::StructuralOperator(std::shared_ptr<InternalForce> internal, RCP<const CrsMatrix> M,
                                       double rayleighK, double rayleighM, std::shared_ptr<const Loads> loads,
                                       ContactManager* contact, DirectLinks* links,
                                       std::unique_ptr<LinearSolver> solver, Teuchos::StackedTimer* timer)
    : internal_(std::move(internal)), mass_(std::move(M), rayleighK, rayleighM, internal_),
      loads_(std::move(loads)), contact_(contact), links_(links), solver_(std::move(solver)), timer_(timer),
      ku_(internal_->map(), 1) {}

// The tangent at u = 0: its matrix object, which each correction refills (evaluateTangent).
const RCP<const CrsMatrix>& StructuralOperator::tangentMatrix() {
  if (K_.is_null()) {
    const Vector zero(internal_->map());
    K_ = internal_->tangent(zero);
  }
  return K_;
}

// The effective system is built at the first correction (an explicit run never builds it).
ContactSystem& StructuralOperator::system() {
  if (system_ && contact_ && contact_->topologyVersion() != systemTopology_) {
    system_.reset();  // a slave node changed master face: a new graph (and factorisation)
    factored_.forget();
  }
  if (!system_) {
    systemTopology_ = contact_ ? contact_->topologyVersion() : 0;
    system_ = std::make_unique<ContactSystem>(tangentMatrix(), mass_.matrix(), contact_,
                                              links_ ? links_->couplings() : std::vector<std::vector<GO>>(), condense_);
    rhs_ = rcp(new MultiVector(system_->map(), 1));
    x_ = rcp(new MultiVector(system_->map(), 1));
    if (system_->projection() && !solver_->setProjection(system_->projection()))
      throw std::logic_error("the linear solver cannot project out the contact multipliers (a direct solver)");
  }
  return *system_;
}

int StructuralOperator::unknowns() const {
  if (system_) return int(system_->map()->getGlobalNumElements());
  return int(internal_->map()->getGlobalNumElements());
}

double StructuralOperator::strainEnergy(const Vector& u) const {
  return internal_->strainEnergy(u, ku_.holds(u, 0) ? &ku_.product(0) : nullptr);
}

void StructuralOperator::applyMass(const Vector& a, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  mass_.applyMass(a, out);
}

void StructuralOperator::applyForces(const Vector& u, const Vector& v, double t, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  internal_->setTime(t);  // the follower loads' ramp, for this residual and its correction's tangent
  internal_->internalForce(u, out);
  if (keepProducts_) {
    ku_.reset(u);
    ku_.write(0).assign(out);
  }
  mass_.addDampingForces(v, out, keepProducts_);
  if (loads_) loads_->subtractFrom(t, out);
}

double StructuralOperator::addConstraintForces(const Vector& u, const Vector& v, Vector& out) {
  if (!contact_ && !links_) return 0.0;
  TimerScope ts(timer_, "Transient: contact");
  if (links_) links_->addForces(u, v, out);
  return contact_ && !forwardIncrement_ ? contact_->addForces(u, out) : 0.0;
}

// K_'s values at u (a linear model: K, always version 0); the finite-strain elements' tangents
// count as assembly.
void StructuralOperator::evaluateTangent(const Vector& u) {
  TimerScope ts(timer_, "Transient: assembly");
  internal_->tangent(u);
}

CorrectionStatus StructuralOperator::solveCorrection(const EffectiveCoefficients& c,
                                                     const Vector& u, const Vector& r, Vector& du) {
  CorrectionStatus st;
  if (restoreKept_) restoreKeptFactorization();
  ContactSystem& sys = system();
  evaluateTangent(u);
  std::vector<char> status = sys.statusKey();
  // The links' tangent, with v following u (dv/du = cv / cd); none for W = M.
  const bool linkTangent = links_ && c.cd > 0.0;
  if (linkTangent) {
    const std::vector<char> lk = links_->tangentKey();
    status.insert(status.end(), lk.begin(), lk.end());
  }
  FactorizationKey key = keyOf(c, std::move(status));
  const KeyChange change = factored_.compare(key);
  if (change != KeyChange::None) {
    {
      TimerScope ts(timer_, "Transient: assembly");
      if (key.tangent != filledTangent_) sys.stiffnessChanged();
      filledTangent_ = key.tangent;
      sys.fill(mass_.massCoefficient(c), mass_.stiffnessCoefficient(c),
                    linkTangent ? links_->tangent(c.cv / c.cd) : std::vector<MatrixEntry>());
    }
    TimerScope ts(timer_, "Transient: linear solve");
    // throws NumericalError when singular
    if (change == KeyChange::StatusOnly)
      solver_->updateMatrix(sys.matrix());  // a change of status: contact rows only
    else
      solver_->setMatrix(sys.matrix());
    factored_.record(std::move(key));
    st.refactored = true;
  }
  {
    TimerScope ts(timer_, "Transient: contact");
    sys.rightHandSide(r, u, *rhs_);
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
    kept_.factored = sys.lastEntries();
    kept_.coefficients = c;
    recordedFactorizations_ = solver_->factorizations();
  }
  st.ok = ls.converged;
  st.iterations = ls.iterations;
  st.message = ls.message;
  if (!st.ok) return st;
  TimerScope ts(timer_, "Transient: contact");
  sys.takeSolution(*x_, du);
  return st;
}

// The key of W = ca M + cv C + cd K_T with the given statuses, at the tangent's version.
FactorizationKey StructuralOperator::keyOf(const EffectiveCoefficients& c, std::vector<char> status) const {
  FactorizationKey k;
  k.coefficients = {c.ca, c.cv, c.cd};
  k.tangent = internal_->tangentVersion();
  k.status = std::move(status);
  return k;
}

// Initial acceleration with massless DOFs (redistributed contact mass): by blocks
// (physics/MasslessInitialAcceleration.hpp), the factorisation of A0 dropped afterwards.
CorrectionStatus StructuralOperator::solveInitialAcceleration(const Vector& u, const Vector& r,
                                                              Vector& a) {
  if (mass_.masslessDofs() == 0) return SecondOrderOperator::solveInitialAcceleration(u, r, a);
  factored_.forget();  // the next correction refactors the effective matrix
  return solveMasslessInitialAcceleration(*tangentMatrix(), *mass_.matrix(), mass_.masslessMask(), *solver_, timer_, r, a);
}

void StructuralOperator::beginStep(const Vector& u, double t, double dt) {
  if (links_) links_->beginStep(dt);
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->beginStep(u, t, dt);
}

double StructuralOperator::elasticTermsNorm(const Vector& u) const { return internal_->termsNorm(u); }

void StructuralOperator::addExplicitContact(const Vector& u, const Vector& uStar, const Vector& inverseMass,
                                            double h, double h2, Vector& a) {
  TimerScope ts(timer_, "Transient: contact");
  contact_->forwardIncrement(u, uStar, inverseMass, h, h2, a);
}

void StructuralOperator::commitMotion(const Vector& u) {
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->commitMotion(u);
}

ConstraintUpdate StructuralOperator::updateConstraints(const Vector& u) {
  ConstraintUpdate up;
  if (!contact_ || forwardIncrement_) return up;
  TimerScope ts(timer_, "Transient: contact");
  const StatusUpdate s = contact_->updateStatus(u);
  up.changed = s.changed;
  up.active = s.active;
  up.summary = std::to_string(s.entered) + " entered, " + std::to_string(s.left) + " left, " +
               std::to_string(s.active) + " active" + (s.where.empty() ? "" : " in " + s.where);
  return up;
}

void StructuralOperator::initializeConstraints(const Vector& u) {
  if (contact_) contact_->initialize(u);
}
ElementValidity StructuralOperator::validity(const Vector& u) const {
  TimerScope ts(timer_, "Transient: validity");
  ElementValidity v = internal_->validity(u);
  if (domain_) domain_->check(u, v);
  if (contact_) contact_->checkPenetration(u, v);
  return v;
}

void StructuralOperator::commit() {
  internal_->commit();
  if (links_) links_->commit();
  if (contact_) contact_->commit();
}
void StructuralOperator::revert() {
  internal_->revert();
  if (links_) links_->revert();
  if (contact_) contact_->revert();
}
void StructuralOperator::archive(StateArchive& a) const {
  internal_->archive(a);
  if (contact_) contact_->archive(a);
  if (links_) links_->archive(a);
  if (system_ && factored_.valid() && solver_->mayKeepFactorization()) {
    KeptFactorization k = kept_;
    k.last = system_->lastEntries();
    k.keyStatus = factored_.key().status;
    k.solverState = solver_->keptState();
    k.archive(a, *internal_->map()->getComm());
  }
}
void StructuralOperator::restore(const StateArchive& a) {
  internal_->restore(a);
  if (contact_) contact_->restore(a);
  if (links_) links_->restore(a);
  restoreKept_ = kept_.restore(a, *internal_->map()->getComm());
}

// The checkpoint's factored matrix, factored again, then its last filled matrix on the
// kept factorisation with the solver's state: the path of the run that wrote it.
void StructuralOperator::restoreKeptFactorization() {
  restoreKept_ = false;
  ContactSystem& sys = system();
  const EffectiveCoefficients& c = kept_.coefficients;
  const double aM = mass_.massCoefficient(c), aK = mass_.stiffnessCoefficient(c);
  TimerScope ts(timer_, "Transient: linear solve");
  sys.fillEntries(aM, aK, kept_.factored);  // rows another rank owns are skipped
  solver_->setMatrix(sys.matrix());
  kept_.factored = sys.lastEntries();
  recordedFactorizations_ = solver_->factorizations();
  sys.fillEntries(aM, aK, kept_.last);
  if (!kept_.solverState.empty() && kept_.solverState[0] != 0) solver_->updateMatrix(sys.matrix());
  solver_->restoreKeptState(kept_.solverState);
  factored_.record(keyOf(c, kept_.keyStatus));
}

}  // namespace choc
