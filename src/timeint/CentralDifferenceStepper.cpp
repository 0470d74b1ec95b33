#include "timeint/CentralDifferenceStepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"

namespace choc {

namespace {

// Whether every entry of u, v and a is finite on every rank: one pass over each (x * 0 is 0 for
// a finite x, NaN for an infinite or NaN one), one reduction.
bool finiteOnEveryRank(const Vector& u, const Vector& v, const Vector& a) {
  double probe = 0.0;
  for (const Vector* x : {&u, &v, &a}) {
    const auto d = x->getData();
    for (const double e : d) probe += e * 0.0;
  }
  int bad = probe == 0.0 ? 0 : 1, any = 0;
  Teuchos::reduceAll(*u.getMap()->getComm(), Teuchos::REDUCE_MAX, bad, Teuchos::outArg(any));
  return any == 0;
}

}  // namespace

CentralDifferenceStepper::CentralDifferenceStepper(ExplicitOperator& op, RCP<const Vector> inverseMass,
                                                   TransientSettings settings, int substeps)
    : StructuralStepper(op, std::move(settings)), xop_(op), inverseMass_(std::move(inverseMass)),
      substeps_(substeps < 1 ? 1 : substeps) {
  auto map = op_.map();
  for (RCP<Vector>* v : {&vHalf_, &r_, &uStar_}) *v = rcp(new Vector(map));
}

void CentralDifferenceStepper::acceleration(const Vector& u, const Vector& vStar, double t, double dt,
                                            Vector& a, double h, double factor) {
  op_.commitMotion(u);  // the previous sub-step ended at u
  op_.beginStep(u, t, dt);
  op_.updateConstraints(u);  // penalty status at u (the only constraints an explicit step takes)
  op_.applyForces(u, vStar, t, *r_);
  op_.addConstraintForces(u, vStar, *r_);  // adds into r: no vector of its own to clear and add
  a.elementWiseMultiply(-1.0, *inverseMass_, *r_, 0.0);
  if (xop_.hasExplicitContact()) {
    uStar_->update(1.0, u, h, vStar, 0.0);
    uStar_->update(factor * h * h, a, 1.0);
    if (rigid_) rigid_->predict(h, factor, *r_, *uStar_);
    xop_.addExplicitContact(u, *uStar_, *inverseMass_, h, factor * h * h, a, *r_);
  }
}

// The initial state's acceleration (with the contact increments of the first sub-step).
void CentralDifferenceStepper::start(double t0, double firstStep, TransientSummary& sum, StepInfo& info) {
  sum.smallestStep = s_.timeStep / substeps_;
  op_.beginStep(*u_, t0, 0.0);
  op_.initializeConstraints(*u_);
  if (rigid_) rigid_->start(*u_, *v_);
  acceleration(*u_, *v_, t0, 0.0, *a_, firstStep / substeps_, 0.5);
  if (rigid_) rigid_->accelerate(*r_, *a_);
  op_.commit();  // every explicit force is accepted: its trial states (links, material points) advance
  info.substep = firstStep / substeps_;
}

// Velocity Verlet (central differences with integer-step velocities): any step length. The
// sub-steps of length h from t up to target; the observers see each but the last as a
// sub-step.
void CentralDifferenceStepper::takeSubsteps(double t, double target, double h) {
  for (int k = 0; k < substeps_; ++k) {
    vHalf_->update(1.0, *v_, 0.5 * h, *a_, 0.0);
    u_->update(h, *vHalf_, 1.0);
    if (rigid_) rigid_->drift(h, *u_, *vHalf_);
    t = k + 1 == substeps_ ? target : t + h;
    xop_.keepProducts(k + 1 == substeps_);  // the step's end state: the energies follow
    acceleration(*u_, *vHalf_, t, h, *a_, h, 1.0);
    op_.commit();
    v_->update(1.0, *vHalf_, 0.5 * h, *a_, 0.0);
    if (rigid_) rigid_->kick(h, *r_, *v_, *a_);
    if (k + 1 < substeps_) notifySubstep(t);
  }
}

void CentralDifferenceStepper::requireFiniteState(double t, long long n) const {
  if (finiteOnEveryRank(*u_, *v_, *a_)) return;  // collective
  char buf[160];
  std::snprintf(buf, sizeof buf, "the state is not finite at t = %.6e s (step %lld): ", t, n);
  throw NumericalError(s_.label + ": " + buf +
                       "the time step exceeds the stability limit of central differences "
                       "(lower 'Time Step' or set 'Stability Check' = 'substep')");
}

void CentralDifferenceStepper::archiveState(StateArchive& a, const StateVectors& vectors) const {
  StructuralStepper::archiveState(a, vectors);
  if (decide_) a.putInt("driver/substeps", substeps_);
}

void CentralDifferenceStepper::restoreState(const StateArchive& a, const StateVectors& vectors) {
  StructuralStepper::restoreState(a, vectors);
  if (decide_ && a.has("driver/substeps")) substeps_ = int(a.getInt("driver/substeps"));
}

Advance CentralDifferenceStepper::advance(const NominalStep& s, StepControl& /*c*/, TransientSummary& sum) {
  if (validityEvery_ > 0 && (s.n - 1) % validityEvery_ == 0) {
    const std::string invalid = checkValidity(*u_, s.t);
    if (!invalid.empty()) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "at t = %.6e s (step %lld): ", s.t, s.n - 1);
      throw InadmissibleState(s_.label + ": " + buf + invalid);
    }
  }
  if (decide_ && interval_ > 0 && (s.n - 1) % interval_ == 0) {
    substeps_ = decide_(*u_, s.t, s.n);
    sum.smallestStep = std::min(sum.smallestStep, (s.target - s.t) / substeps_);
  }
  const double h = (s.target - s.t) / substeps_;
  sum.substeps += substeps_;
  sum.maxSubsteps = std::max(sum.maxSubsteps, substeps_);
  try {
    takeSubsteps(s.t, s.target, h);
  } catch (const InadmissibleState& e) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "in the step from t = %.6e s to %.6e s (step %lld): ", s.t, s.target, s.n);
    throw NumericalError(s_.label + ": " + buf + e.what());
  }
  requireFiniteState(s.target, s.n);
  Advance a;
  a.time = s.target;
  a.dt = s.target - s.t;
  a.substep = h;
  return a;
}

}  // namespace choc
