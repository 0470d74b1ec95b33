#include "timeint/TransientDriver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "timeint/TimeGrid.hpp"

namespace choc {

TransientDriver::TransientDriver(SecondOrderOperator& op, NewmarkFamily scheme,
                                 TransientSettings settings)
    : op_(op), scheme_(std::move(scheme)), s_(std::move(settings)) {
  auto map = op_.map();
  for (RCP<Vector>* v : {&u0_, &v0_, &a0_, &Ma0_, &F0_, &Ma1_, &F1_, &u1_, &v1_, &a1_, &uTilde_, &vTilde_,
                         &inertia_, &forces_, &fc_, &change_})
    *v = rcp(new Vector(map));
}

void TransientDriver::notify(const StepInfo& info) {
  for (StepObserver* o : observers_) o->stepAccepted(info, *u0_, *v0_, *a0_);
}

NewtonOutcome TransientDriver::attempt(double t, double dt) {
  const double beta = scheme_.beta(), gamma = scheme_.gamma();
  const double af = scheme_.alphaF(), am = scheme_.alphaM();
  const double t1 = t + dt;
  op_.beginStep(*u0_, t1, dt);
  // Predictors: u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, v~ = v_n + dt (1 - gamma) a_n.
  uTilde_->update(1.0, *u0_, dt, *v0_, 0.0);
  uTilde_->update(dt * dt * (0.5 - beta), *a0_, 1.0);
  vTilde_->update(1.0, *v0_, dt * (1 - gamma), *a0_, 0.0);
  // Start Newton from a_{n+1} = a_n.
  u1_->update(1.0, *uTilde_, beta * dt * dt, *a0_, 0.0);
  const EffectiveCoefficients c = scheme_.effectiveCoefficients(dt);
  op_.applyMass(*u1_, *inertia_);
  // Round-off floor of the residual: the largest terms it sums, ||c_a M u_{n+1}|| and, for a
  // body carried far by a rigid motion (whose elastic force K u cancels terms of size |K||u|),
  // || |K| |u_{n+1}| ||.
  const double roundoff = std::max(c.ca * inertia_->norm2(), op_.elasticTermsNorm(*u1_));
  auto residual = [&](const Vector& u, Vector& r) {
    a1_->update(1.0 / (beta * dt * dt), u, -1.0 / (beta * dt * dt), *uTilde_, 0.0);
    v1_->update(1.0, *vTilde_, gamma * dt, *a1_, 0.0);
    // The unweighted M a_{n+1} and F_{n+1} are kept: the last residual of a converged step is
    // evaluated at its u_{n+1}, so they become the next step's M a_n and F_n unrecomputed.
    op_.applyMass(*a1_, *inertia_);
    if (am != 0.0) {
      Ma1_->assign(*inertia_);
      inertia_->update(am, *Ma0_, 1 - am);
    }
    op_.applyForces(u, *v1_, t1, *forces_);
    if (af != 0.0) {
      F1_->assign(*forces_);
      forces_->update(af, *F0_, 1 - af);
    }
    fc_->putScalar(0.0);
    const double cons = op_.addConstraintForces(u, *v1_, *fc_);
    ResidualNorms n;
    n.reference = std::max({inertia_->norm2(), forces_->norm2(), fc_->norm2()});
    r.update(1.0, *inertia_, 1.0, *forces_, 0.0);
    r.update(1.0, *fc_, 1.0);
    const double rn = r.norm2();
    n.residual = std::sqrt(rn * rn + cons * cons);
    n.constraintResidual = cons;
    n.roundoff = roundoff;
    change_->update(1.0, u, -1.0, *u0_, 0.0);
    n.incrementScale = change_->norm2();
    n.solutionNorm = u.norm2();
    return n;
  };
  NewtonOutcome out = solveNewtonActiveSet(op_, c, residual,
                                           *u1_, s_.newton);
  if (out.converged) {  // the state that goes with the converged u_{n+1}
    a1_->update(1.0 / (beta * dt * dt), *u1_, -1.0 / (beta * dt * dt), *uTilde_, 0.0);
    v1_->update(1.0, *vTilde_, gamma * dt, *a1_, 0.0);
  }
  return out;
}

void TransientDriver::initialState(TransientSummary& sum) {
  // Initial acceleration from equilibrium: M a0 = -(F(u0, v0, t0) + f_c(u0)).
  const double t0 = s_.startTime;
  op_.beginStep(*u0_, t0, 0.0);
  op_.initializeConstraints(*u0_);
  Vector r(op_.map());
  op_.applyForces(*u0_, *v0_, t0, r);
  fc_->putScalar(0.0);
  op_.addConstraintForces(*u0_, *v0_, *fc_);
  r.update(1.0, *fc_, 1.0);
  const CorrectionStatus cs = op_.solveInitialAcceleration(*u0_, r, *a0_);
  if (cs.refactored) ++sum.refactorizations;
  if (!cs.ok)
    throw NumericalError(s_.label + ": initial acceleration: linear solve failed: " + cs.message);
  op_.saveState();
}

void StepLoop::putState(StateArchive& a, const StateVectors& vectors, const ConstState& s,
                        const SecondOrderOperator& op) {
  vectors.put(a, "driver/u", s.u);
  vectors.put(a, "driver/v", s.v);
  vectors.put(a, "driver/a", s.a);
  a.putDouble("driver/time", s.time);
  a.putInt("driver/nominal", s.nominal);
  a.putPod("driver/summary", s.summary);
  op.archive(a);
}

void StepLoop::getState(const Resume& r, const State& s, SecondOrderOperator& op) {
  r.vectors.get(r.archive, "driver/u", s.u);
  r.vectors.get(r.archive, "driver/v", s.v);
  r.vectors.get(r.archive, "driver/a", s.a);
  s.time = r.archive.getDouble("driver/time");
  s.nominal = r.archive.getInt("driver/nominal");
  s.summary = r.archive.getPod<TransientSummary>("driver/summary");
  op.unarchive(r.archive);
  op.saveState();
}

void TransientDriver::archive(StateArchive& a, const StateVectors& vectors) const {
  putState(a, vectors, {*u0_, *v0_, *a0_, t_, nominal_, sum_}, op_);
}

// The state the run starts from: the checkpoint's, or (u, v) at startTime with the initial
// acceleration from equilibrium; then the weighted terms M a_n and F_n of the first step.
void TransientDriver::startState(const Vector& u, const Vector& v, const Resume* resume) {
  TransientSummary& sum = sum_;
  if (resume) {
    getState(*resume, {*u0_, *v0_, *a0_, t_, nominal_, sum}, op_);
  } else {
    u0_->assign(u);
    v0_->assign(v);
    t_ = s_.startTime;
    nominal_ = 0;
    initialState(sum);
    sum.smallestStep = s_.timeStep;
  }
  if (scheme_.alphaM() != 0.0) op_.applyMass(*a0_, *Ma0_);
  if (scheme_.alphaF() != 0.0) op_.applyForces(*u0_, *v0_, t_, *F0_);
}

void TransientDriver::countIterations(const NewtonOutcome& out) {
  sum_.newtonIterations += out.iterations;
  sum_.activeSetIterations += out.activeSetIterations;
  sum_.refactorizations += out.refactorizations;
  sum_.krylovIterations += out.krylovIterations;
}

// A failed attempt: back to the accepted state; the run stops when no cut of dt is left.
void TransientDriver::rejectAttempt(double t, double h, int cuts, const NewtonOutcome& out) {
  op_.restoreState();
  ++sum_.failedSteps;
  if (cuts < s_.maxCuts) return;
  char buf[200];
  std::snprintf(buf, sizeof buf, "step from t = %.6e s with dt = %.3e s failed after %d cut(s) of dt: ",
                t, h, cuts);
  throw NumericalError(s_.label + ": " + buf + out.message +
                       (s_.maxCuts == 0 ? " (dt cutting is off: set 'Maximum Step Cuts')"
                                        : " (raise 'Maximum Step Cuts' or lower 'Time Step')"));
}

// The converged attempt that reached t: n+1 becomes n.
void TransientDriver::acceptAttempt(double t) {
  std::swap(u0_, u1_);
  std::swap(v0_, v1_);
  std::swap(a0_, a1_);
  op_.acceptStep(*u0_);
  op_.saveState();
  std::swap(Ma0_, Ma1_);  // M a and F of the converged u (zero-weighted when alpha is 0)
  if (scheme_.alphaF() != 0.0 && op_.forcesVaryInTime())
    op_.applyForces(*u0_, *v0_, t, *F0_);  // at t itself (t + h can differ by round-off)
  else
    std::swap(F0_, F1_);
}

// Nominal step n from t to its end, by attempts cut on failure; each accepted one is shown to
// the observers.
void TransientDriver::nominalStep(long long n, long long nominal, double& t, StepInfo& info) {
  TransientSummary& sum = sum_;
  const double dt = s_.timeStep;
  const double target = n == nominal ? s_.endTime : s_.startTime + double(n) * dt;
  double h = target - t;
  int cuts = 0;
  while (t < target) {
    const bool finalSub = h >= target - t - 1e-9 * dt;
    // A whole nominal step uses dt itself (not target - t, which differs by round-off and
    // would change the effective matrix's key).
    if (finalSub) h = std::abs(target - t - dt) <= 1e-9 * dt ? dt : target - t;
    NewtonOutcome out = attempt(t, h);
    countIterations(out);
    if (!out.converged) {
      rejectAttempt(t, h, cuts, out);
      ++cuts;
      h *= s_.cutFactor;
      continue;
    }
    t = finalSub ? target : t + h;
    acceptAttempt(t);
    ++sum.steps;
    sum.maxNewtonPerStep = std::max(sum.maxNewtonPerStep, out.iterations);
    sum.smallestStep = std::min(sum.smallestStep, h);
    t_ = t;
    if (t >= target) nominal_ = n;
    info.step = sum.steps;
    info.time = t;
    info.dt = h;
    info.newton = out;
    info.cuts = cuts;
    info.last = n == nominal && t >= target;
    info.boundary = t >= target;
    info.nominal = nominal_;
    notify(info);
  }
}

TransientSummary TransientDriver::run(Vector& u, Vector& v, const Resume* resume) {
  TransientSummary& sum = sum_;
  sum = TransientSummary();
  const double dt = s_.timeStep, t0 = s_.startTime;
  if (!(dt > 0) || !(s_.endTime > t0))
    throw std::invalid_argument("TransientDriver: needs dt > 0 and endTime > startTime");
  StepInfo info;
  startState(u, v, resume);
  info.time = t_;
  info.step = sum.steps;
  info.nominal = nominal_;
  if (!resume) notify(info);

  const double span = s_.endTime - t0;
  // Bounded by the analysis's 'Maximum Steps' (checked in its settings): the cast is exact.
  const auto nominal = static_cast<long long>(nominalSteps(t0, t0 + span, dt));
  double t = t_;
  for (long long n = nominal_ + 1; n <= nominal; ++n) nominalStep(n, nominal, t, info);
  u.assign(*u0_);
  v.assign(*v0_);
  return sum;
}

}  // namespace choc
