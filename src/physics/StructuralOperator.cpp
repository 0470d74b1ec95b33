#include "physics/StructuralOperator.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

namespace {

RCP<const CrsMatrix> initialTangent(InternalForce& internal) {
  const Vector zero(internal.map());
  return internal.tangent(zero);
}

}  // namespace

StructuralOperator::StructuralOperator(std::shared_ptr<InternalForce> internal, RCP<const CrsMatrix> M,
                                       double rayleighK, double rayleighM, std::shared_ptr<const Loads> loads,
                                       ContactManager* contact, DirectLinks* links,
                                       std::unique_ptr<LinearSolver> solver, Teuchos::StackedTimer* timer)
    : internal_(std::move(internal)), K_(initialTangent(*internal_)), M_(std::move(M)), aK_(rayleighK), aM_(rayleighM), loads_(std::move(loads)),
      contact_(contact), links_(links), solver_(std::move(solver)), timer_(timer),
      ku_(K_->getRowMap(), 1), vProducts_(K_->getRowMap(), 2) {

  tmp_ = rcp(new Vector(K_->getRowMap()));
  energyTmp_ = rcp(new Vector(K_->getRowMap()));
  // Massless DOFs: rows of M without a non-zero entry.
  const size_t nLocal = M_->getNodeNumRows();
  massless_.assign(nLocal, 0);
  long long mine = 0;
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocal; ++i) {
    const GO g = M_->getRowMap()->getGlobalElement(LO(i));
    const size_t n = M_->getNumEntriesInGlobalRow(g);
    ci.resize(n);
    cv.resize(n);
    size_t got = 0;
    M_->getGlobalRowCopy(g, ci(), cv(), got);
    bool zero = true;
    for (size_t k = 0; k < got; ++k) zero = zero && cv[k] == 0.0;
    massless_[i] = zero;
    mine += zero;
  }
  Teuchos::reduceAll<int, long long>(*M_->getComm(), Teuchos::REDUCE_SUM, mine,
                                     Teuchos::outArg(masslessGlobal_));
}

// The effective system is built at the first correction (an explicit run never builds it).
ContactSystem& StructuralOperator::system() {
  if (system_ && contact_ && contact_->topologyVersion() != systemTopology_) {
    system_.reset();  // a slave node changed master face: a new graph (and factorisation)
    factored_.forget();
  }
  if (!system_) {
    systemTopology_ = contact_ ? contact_->topologyVersion() : 0;
    system_ = std::make_unique<ContactSystem>(K_, M_, contact_,
                                              links_ ? links_->couplings() : std::vector<std::vector<GO>>());
    rhs_ = rcp(new MultiVector(system_->map(), 1));
    x_ = rcp(new MultiVector(system_->map(), 1));
  }
  return *system_;
}

int StructuralOperator::unknowns() const {
  if (system_) return int(system_->map()->getGlobalNumElements());
  return int(K_->getRowMap()->getGlobalNumElements());
}

double StructuralOperator::kineticEnergy(const Vector& v) const {
  if (vProducts_.holds(v, kMv)) return 0.5 * v.dot(vProducts_.product(kMv));
  applyMassTo(v, *energyTmp_);
  return 0.5 * v.dot(*energyTmp_);
}

double StructuralOperator::strainEnergy(const Vector& u) const {
  return internal_->strainEnergy(u, ku_.holds(u, 0) ? &ku_.product(0) : nullptr);
}

// v^T C v = aK v^T K v + aM v^T M v.
double StructuralOperator::dampingPower(const Vector& v, double kinetic) const {
  double power = aM_ * 2.0 * kinetic;
  if (aK_ != 0.0) {
    if (vProducts_.holds(v, kKv)) return power + aK_ * v.dot(vProducts_.product(kKv));
    internal_->applyDampingStiffness(v, *energyTmp_);
    power += aK_ * v.dot(*energyTmp_);
  }
  return power;
}

void StructuralOperator::useDiagonalMass(RCP<const Vector> m) { massDiagonal_ = std::move(m); }

void StructuralOperator::applyMassTo(const Vector& x, Vector& out) const {
  if (massDiagonal_.is_null()) M_->apply(x, out);
  else out.elementWiseMultiply(1.0, *massDiagonal_, x, 0.0);
}

void StructuralOperator::applyMass(const Vector& a, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  applyMassTo(a, out);
}

void StructuralOperator::applyForces(const Vector& u, const Vector& v, double t, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  internal_->internalForce(u, out);
  if (keepProducts_) {
    ku_.reset(u);
    ku_.write(0).assign(out);
    vProducts_.reset(v);
  }
  // K v and M v straight into the cache's buffers when kept.
  if (aK_ != 0.0) {
    Vector& Kv = keepProducts_ ? vProducts_.write(kKv) : *tmp_;
    internal_->applyDampingStiffness(v, Kv);
    out.update(aK_, Kv, 1.0);
  }
  if (aM_ != 0.0 && !keepProducts_ && !massDiagonal_.is_null()) {
    out.elementWiseMultiply(aM_, *massDiagonal_, v, 1.0);  // out += aM m .* v in one pass
  } else if (aM_ != 0.0) {
    Vector& Mv = keepProducts_ ? vProducts_.write(kMv) : *tmp_;
    applyMassTo(v, Mv);
    out.update(aM_, Mv, 1.0);
  }
  if (loads_) loads_->subtractFrom(t, out);
}

double StructuralOperator::addConstraintForces(const Vector& u, const Vector& v, Vector& out) {
  if (!contact_ && !links_) return 0.0;
  TimerScope ts(timer_, "Transient: contact");
  if (links_) links_->addForces(u, v, out);
  return contact_ && !forwardIncrement_ ? contact_->addForces(u, out) : 0.0;
}

CorrectionStatus StructuralOperator::solveCorrection(const EffectiveCoefficients& c,
                                                     const Vector& u, const Vector& r, Vector& du) {
  CorrectionStatus st;
  if (restoreKept_) restoreKeptFactorization();
  ContactSystem& sys = system();
  internal_->tangent(u);  // K_'s values at u (a linear model: K, always version 0)
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
      sys.fill(c.ca + c.cv * aM_, c.cd + c.cv * aK_,
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

// Initial acceleration with massless DOFs (redistributed contact mass). M = [M_mm 0; 0 0]
// (z: the DOFs whose mass row is zero, the nodes of the contact surfaces). Rows m give a_m
// from M_mm a_m = -r_m: the contact forces act on contact-surface DOFs only, so they do not
// enter r_m. Rows z carry no inertia: they are the static equilibrium K_zm u_m + K_zz u_z
// + f_c,z = f_z, which holds at t0 and which every step re-imposes at t_{n+1} whatever a_z
// (u_z is found statically; a_z only feeds v_z through the Newmark relations, and v_z acts
// only through Rayleigh damping). The consistent value is the second time derivative of that
// equilibrium with the contact status and pressures frozen and constant loads:
// K_zz a_z = -K_zm a_m. Both come from A0 = [M_mm 0; 0 K_zz] (symmetric, non-singular: a
// contact-surface node is tied elastically to the massive nodes): a first solve with
// b = (-r_m, 0) gives a_m, a second with b = (-r_m, -(K [a_m; 0])_z) gives (a_m, a_z). The
// contact pressures keep their initial values (the reactions of the static rows, found by the
// first step). The factorisation of A0 is dropped afterwards (factored_.forget()).
CorrectionStatus StructuralOperator::solveInitialAcceleration(const Vector& u, const Vector& r,
                                                              Vector& a) {
  if (masslessGlobal_ == 0) return SecondOrderOperator::solveInitialAcceleration(u, r, a);
  CorrectionStatus st;
  auto rowMap = K_->getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  RCP<CrsMatrix> A0 = initialAccelerationMatrix();
  TimerScope ts(timer_, "Transient: linear solve");
  factored_.forget();  // the next correction refactors the effective matrix
  solver_->setMatrix(A0);
  st.refactored = true;
  MultiVector b(rowMap, 1), x(rowMap, 1);
  {
    auto rd = r.getData();
    auto bd = b.getDataNonConst(0);
    for (size_t i = 0; i < nLocal; ++i) bd[i] = massless_[i] ? 0.0 : -rd[i];
  }
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) masslessRightHandSide(x, b);
    x.putScalar(0.0);
    const LinearSolveStatus ls = solver_->solve(b, x);
    st.ok = ls.converged;
    st.iterations += ls.iterations;
    st.message = ls.message;
    if (!st.ok) return st;
  }
  (void)u;
  a.assign(*x.getVector(0));
  return st;
}

// A0 = [M_mm 0; 0 K_zz]: the rows of M on the DOFs with mass, the rows of K restricted to the
// massless columns on the others.
RCP<CrsMatrix> StructuralOperator::initialAccelerationMatrix() const {
  TimerScope ts(timer_, "Transient: assembly");
  auto rowMap = K_->getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  const std::vector<std::vector<std::pair<GO, double>>> rows = initialAccelerationRows();
  std::vector<size_t> counts(nLocal);
  for (size_t i = 0; i < nLocal; ++i) counts[i] = rows[i].size();
  RCP<CrsMatrix> A0 = rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
  for (size_t i = 0; i < nLocal; ++i) {
    std::vector<GO> c;
    std::vector<double> v;
    for (const auto& [cc, vv] : rows[i]) {
      c.push_back(cc);
      v.push_back(vv);
    }
    A0->insertGlobalValues(rowMap->getGlobalElement(LO(i)), Teuchos::ArrayView<const GO>(c),
                           Teuchos::ArrayView<const double>(v));
  }
  A0->fillComplete(rowMap, rowMap);
  return A0;
}

// A0's entries by local row (global column, value).
std::vector<std::vector<std::pair<GO, double>>> StructuralOperator::initialAccelerationRows() const {
  auto rowMap = K_->getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  Vector zRow(rowMap);
  {
    auto z = zRow.getDataNonConst();
    for (size_t i = 0; i < nLocal; ++i) z[i] = massless_[i] ? 1.0 : 0.0;
  }
  Vector zCol(K_->getColMap());
  zCol.doImport(zRow, Tpetra::Import<LO, GO>(rowMap, K_->getColMap()), Tpetra::INSERT);
  auto zc = zCol.getData();
  auto colMap = K_->getColMap();
  std::vector<std::vector<std::pair<GO, double>>> rows(nLocal);
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocal; ++i) {
    const GO g = rowMap->getGlobalElement(LO(i));
    const CrsMatrix& X = massless_[i] ? *K_ : *M_;
    const size_t n = X.getNumEntriesInGlobalRow(g);
    ci.resize(n);
    cv.resize(n);
    size_t got = 0;
    X.getGlobalRowCopy(g, ci(), cv(), got);
    for (size_t k = 0; k < got; ++k)
      if (!massless_[i] || zc[colMap->getLocalElement(ci[k])] != 0.0) rows[i].emplace_back(ci[k], cv[k]);
  }
  return rows;
}

// The second solve's right-hand side on the massless rows: b_z = -(K [a_m; 0])_z, from the
// first solve's x = (a_m, a_z) (whose a_z it zeroes).
void StructuralOperator::masslessRightHandSide(MultiVector& x, MultiVector& b) const {
  auto rowMap = K_->getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  {
    auto xd = x.getDataNonConst(0);
    for (size_t i = 0; i < nLocal; ++i)
      if (massless_[i]) xd[i] = 0.0;
  }
  Vector y(rowMap);
  K_->apply(*x.getVector(0), y);
  auto yd = y.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < nLocal; ++i)
    if (massless_[i]) bd[i] = -yd[i];
}

void StructuralOperator::beginStep(const Vector& u, double t, double dt) {
  if (links_) links_->beginStep(dt);
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->beginStep(u, t, dt);
}

double StructuralOperator::elasticTermsNorm(const Vector& u) const { return internal_->termsNorm(u); }

void StructuralOperator::addExplicitContact(const Vector& uStar, const Vector& inverseMass, double h2,
                                            Vector& a) {
  TimerScope ts(timer_, "Transient: contact");
  contact_->forwardIncrement(uStar, inverseMass, h2, a);
}

void StructuralOperator::acceptStep(const Vector& u) {
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->commitStep(u);
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
void StructuralOperator::saveState() {
  internal_->commit();
  if (links_) links_->commit();
  if (contact_) contact_->save();
}
void StructuralOperator::restoreState() {
  internal_->revert();
  if (contact_) contact_->restore();
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
    k.archive(a, *K_->getComm());
  }
}
void StructuralOperator::unarchive(const StateArchive& a) {
  internal_->unarchive(a);
  if (contact_) contact_->unarchive(a);
  if (links_) links_->unarchive(a);
  restoreKept_ = kept_.unarchive(a, *K_->getComm());
}

// The checkpoint's factored matrix, factored again, then its last filled matrix on the
// kept factorisation with the solver's state: the path of the run that wrote it.
void StructuralOperator::restoreKeptFactorization() {
  restoreKept_ = false;
  ContactSystem& sys = system();
  const EffectiveCoefficients& c = kept_.coefficients;
  const double aM = c.ca + c.cv * aM_, aK = c.cd + c.cv * aK_;
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
