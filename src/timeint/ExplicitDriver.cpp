#include "timeint/ExplicitDriver.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "timeint/TimeGrid.hpp"

namespace choc {

ExplicitDriver::ExplicitDriver(ExplicitOperator& op, RCP<const Vector> inverseMass,
                               TransientSettings settings, int substeps)
    : op_(op), inverseMass_(std::move(inverseMass)), s_(std::move(settings)),
      substeps_(substeps < 1 ? 1 : substeps) {
  auto map = op_.map();
  for (RCP<Vector>* v : {&u_, &vHalf_, &a_, &v_, &r_, &uStar_}) *v = rcp(new Vector(map));
}

void ExplicitDriver::notify(const StepInfo& info) {
  for (StepObserver* o : observers_) o->stepAccepted(info, *u_, *v_, *a_);
}

void ExplicitDriver::acceleration(const Vector& u, const Vector& vStar, double t, double dt, Vector& a,
                                  double h, double factor) {
  op_.acceptStep(u);  // the previous sub-step ended at u
  op_.beginStep(u, t, dt);
  op_.updateConstraints(u);  // penalty status at u (the only constraints an explicit step takes)
  op_.applyForces(u, vStar, t, *r_);
  op_.addConstraintForces(u, vStar, *r_);  // adds into r: no vector of its own to clear and add
  a.elementWiseMultiply(-1.0, *inverseMass_, *r_, 0.0);
  if (op_.hasExplicitContact()) {
    uStar_->update(1.0, u, h, vStar, 0.0);
    uStar_->update(factor * h * h, a, 1.0);
    op_.addExplicitContact(*uStar_, *inverseMass_, factor * h * h, a);
  }
  op_.saveState();  // the links' state advances with the step
}

void ExplicitDriver::archive(StateArchive& a, const StateVectors& vectors) const {
  putState(a, vectors, {*u_, *v_, *a_, t_, nominal_, sum_}, op_);
}

// The initial state: (u, v) at startTime with its acceleration (with the contact increments
// of the first sub-step), shown to the observers.
void ExplicitDriver::startState(const Vector& u, const Vector& v, StepInfo& info) {
  TransientSummary& sum = sum_;
  const double dt = s_.timeStep, t0 = s_.startTime;
  sum = TransientSummary();
  sum.smallestStep = dt / substeps_;
  u_->assign(u);
  v_->assign(v);
  t_ = t0;
  nominal_ = 0;
  op_.beginStep(*u_, t0, 0.0);
  op_.initializeConstraints(*u_);
  const double target1 = std::min(s_.endTime, t0 + dt);
  acceleration(*u_, *v_, t0, 0.0, *a_, (target1 - t0) / substeps_, 0.5);
  info.time = t_;
  info.substep = (target1 - t0) / substeps_;
  notify(info);
}

// Velocity Verlet (central differences with integer-step velocities): any step length. The
// sub-steps of length h up to target; the observers see each but the last as a sub-step.
void ExplicitDriver::takeSubsteps(double target, double h) {
  for (int k = 0; k < substeps_; ++k) {
    vHalf_->update(1.0, *v_, 0.5 * h, *a_, 0.0);
    u_->update(h, *vHalf_, 1.0);
    const double t = k + 1 == substeps_ ? target : t_ + h;
    op_.keepProducts(k + 1 == substeps_);  // the step's end state: the energies follow
    acceleration(*u_, *vHalf_, t, h, *a_, h, 1.0);
    v_->update(1.0, *vHalf_, 0.5 * h, *a_, 0.0);
    t_ = t;
    if (k + 1 < substeps_)
      for (StepObserver* o : observers_) o->substepTaken(t_, *u_, *v_);
  }
}

void ExplicitDriver::requireFiniteState(long long n) const {
  const double size = u_->normInf() + v_->normInf() + a_->normInf();  // collective
  if (std::isfinite(size)) return;
  char buf[160];
  std::snprintf(buf, sizeof buf, "the state is not finite at t = %.6e s (step %lld): ", t_, n);
  throw NumericalError(s_.label + ": " + buf +
                       "the time step exceeds the stability limit of central differences "
                       "(lower 'Time Step' or set 'Stability Check' = 'substep')");
}

TransientSummary ExplicitDriver::run(Vector& u, Vector& v, const Resume* resume) {
  TransientSummary& sum = sum_;
  const double dt = s_.timeStep, t0 = s_.startTime;
  if (!(dt > 0) || !(s_.endTime > t0))
    throw std::invalid_argument("ExplicitDriver: needs dt > 0 and endTime > startTime");
  StepInfo info;
  if (resume)
    getState(*resume, {*u_, *v_, *a_, t_, nominal_, sum}, op_);
  else
    startState(u, v, info);
  // Bounded by the analysis's 'Maximum Steps' (checked in its settings): the cast is exact.
  const auto nominal = static_cast<long long>(nominalSteps(t0, s_.endTime, dt));
  for (long long n = nominal_ + 1; n <= nominal; ++n) {
    const double target = n == nominal ? s_.endTime : t0 + double(n) * dt;
    const double tStart = t_, h = (target - t_) / substeps_;
    takeSubsteps(target, h);
    requireFiniteState(n);
    nominal_ = n;
    ++sum.steps;
    sum.smallestStep = std::min(sum.smallestStep, h);
    info.step = sum.steps;
    info.time = t_;
    info.dt = t_ - tStart;
    info.last = n == nominal;
    info.boundary = true;
    info.nominal = nominal_;
    info.substep = h;
    notify(info);
  }
  u.assign(*u_);
  v.assign(*v_);
  return sum;
}

}  // namespace choc
