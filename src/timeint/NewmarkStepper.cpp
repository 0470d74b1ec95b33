#include "timeint/NewmarkStepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"

namespace choc {

NewmarkStepper::NewmarkStepper(SecondOrderOperator& op, NewmarkFamily scheme, TransientSettings settings)
    : StructuralStepper(op, std::move(settings)), scheme_(std::move(scheme)) {
  auto map = op_.map();
  for (RCP<Vector>* v : {&Ma0_, &F0_, &Ma1_, &F1_, &u1_, &v1_, &a1_, &uTilde_, &vTilde_, &inertia_, &forces_,
                         &fc_, &change_})
    *v = rcp(new Vector(map));
}

NewtonOutcome NewmarkStepper::attempt(double t, double dt) {
  try {
    return attemptWithin(t, dt);
  } catch (const InadmissibleState& e) {
    NewtonOutcome out;
    out.message = e.what();
    return out;
  }
}

NewtonOutcome NewmarkStepper::attemptWithin(double t, double dt) {
  const double beta = scheme_.beta(), gamma = scheme_.gamma();
  const double af = scheme_.alphaF(), am = scheme_.alphaM();
  const double t1 = t + dt;
  op_.beginStep(*u_, t1, dt);
  // Predictors: u~ = u_n + dt v_n + dt^2 (1/2 - beta) a_n, v~ = v_n + dt (1 - gamma) a_n.
  uTilde_->update(1.0, *u_, dt, *v_, 0.0);
  uTilde_->update(dt * dt * (0.5 - beta), *a_, 1.0);
  vTilde_->update(1.0, *v_, dt * (1 - gamma), *a_, 0.0);
  startIterate(dt);
  const EffectiveCoefficients c = scheme_.effectiveCoefficients(dt);
  op_.applyMass(*u1_, *inertia_);
  // Round-off floor of the residual: the largest terms it sums, ||c_a M u_{n+1}|| and || |K|
  // |u_{n+1}| || (a rigid motion's K u, a slender solid's internal forces 1e6 times its loads),
  // at the predictor and, once a residual is 1e-3 of the reference, at that iterate (a first
  // step from rest has no elastic terms at its predictor).
  double roundoff = std::max(c.ca * inertia_->norm2(), op_.elasticTermsNorm(*u1_));
  bool floorAtIterate = false;
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
    if (!floorAtIterate && n.residual < 1e-3 * n.reference) {
      roundoff = std::max(roundoff, op_.elasticTermsNorm(u));
      floorAtIterate = true;
    }
    n.roundoff = roundoff;
    change_->update(1.0, u, -1.0, *u_, 0.0);
    n.incrementScale = change_->norm2();
    n.solutionNorm = u.norm2();
    return n;
  };
  NewtonOutcome out = solveNewtonActiveSet(op_, c, residual, *u1_, s_.newton);
  if (out.converged) {  // the state that goes with the converged u_{n+1}
    a1_->update(1.0 / (beta * dt * dt), *u1_, -1.0 / (beta * dt * dt), *uTilde_, 0.0);
    v1_->update(1.0, *vTilde_, gamma * dt, *a1_, 0.0);
  }
  return out;
}

// The initial acceleration from equilibrium: M a0 = -(F(u0, v0, t0) + f_c(u0)).
void NewmarkStepper::start(double t0, double /*firstStep*/, TransientSummary& sum, StepInfo& /*info*/) {
  op_.beginStep(*u_, t0, 0.0);
  op_.initializeConstraints(*u_);
  Vector r(op_.map());
  op_.applyForces(*u_, *v_, t0, r);
  fc_->putScalar(0.0);
  op_.addConstraintForces(*u_, *v_, *fc_);
  r.update(1.0, *fc_, 1.0);
  const CorrectionStatus cs = op_.solveInitialAcceleration(*u_, r, *a_);
  if (cs.refactored) ++sum.refactorizations;
  if (!cs.ok)
    throw NumericalError(s_.label + ": initial acceleration: linear solve failed: " + cs.message);
  op_.commit();
  sum.smallestStep = s_.timeStep;
  weightedTerms(t0);
}

void NewmarkStepper::weightedTerms(double t) {
  if (scheme_.alphaM() != 0.0) op_.applyMass(*a_, *Ma0_);
  if (scheme_.alphaF() != 0.0) op_.applyForces(*u_, *v_, t, *F0_);
}

// HHT's weighted F(u_n) is the one the step computed at its converged u: computed again from the
// committed material state, a plastic point's stress returns to the same value only to round-off
// (measured: 1e-16 at the first step after a restart of the implicit Taylor bar, 1e-11 twenty
// steps later), so the checkpoint keeps it.
void NewmarkStepper::archiveState(StateArchive& a, const StateVectors& vectors) const {
  StructuralStepper::archiveState(a, vectors);
  if (!massless_.empty()) {
    vectors.put(a, "driver/lastIncrement", *lastIncrement_);
    vectors.put(a, "driver/previousIncrement", *previousIncrement_);
    a.putVector("driver/masslessSteps", std::vector<double>{lastStep_, previousStep_});
  }
  if (scheme_.alphaF() != 0.0) vectors.put(a, "driver/weightedForce", *F0_);
}

void NewmarkStepper::restoreState(const StateArchive& a, const StateVectors& vectors) {
  StructuralStepper::restoreState(a, vectors);
  if (!massless_.empty() && a.has("driver/lastIncrement")) {
    vectors.get(a, "driver/lastIncrement", *lastIncrement_);
    vectors.get(a, "driver/previousIncrement", *previousIncrement_);
    const std::vector<double> steps = a.getVector<double>("driver/masslessSteps");
    lastStep_ = steps.at(0);
    previousStep_ = steps.at(1);
  }
  if (scheme_.alphaF() == 0.0 || !a.has("driver/weightedForce")) return weightedTerms(a.getDouble("driver/time"));
  if (scheme_.alphaM() != 0.0) op_.applyMass(*a_, *Ma0_);
  vectors.get(a, "driver/weightedForce", *F0_);
}

void NewmarkStepper::countIterations(const NewtonOutcome& out, TransientSummary& sum) const {
  sum.newtonIterations += out.iterations;
  sum.activeSetIterations += out.activeSetIterations;
  sum.refactorizations += out.refactorizations;
  sum.krylovIterations += out.krylovIterations;
  sum.backtracks += out.backtracks;
}

// A failed attempt: back to the accepted state; the run stops when no cut of dt is left.
void NewmarkStepper::rejectAttempt(double t, double h, int cuts, const NewtonOutcome& out,
                                   TransientSummary& sum) {
  op_.revert();
  ++sum.failedSteps;
  if (cuts < s_.maxCuts) return;
  char buf[200];
  std::snprintf(buf, sizeof buf, "step from t = %.6e s with dt = %.3e s failed after %d cut(s) of dt: ",
                t, h, cuts);
  throw NumericalError(s_.label + ": " + buf + out.message +
                       (s_.maxCuts == 0 ? " (dt cutting is off: set 'Maximum Step Cuts')"
                                        : " (raise 'Maximum Step Cuts' or lower 'Time Step')"));
}

void NewmarkStepper::extrapolateMassless(std::vector<char> mask) {
  massless_ = std::move(mask);
  lastIncrement_ = rcp(new Vector(op_.map()));  // only runs with massless DOFs hold them
  previousIncrement_ = rcp(new Vector(op_.map()));
}

// Newton's first iterate: a_{n+1} = a_n, u1 = u~ + beta dt^2 a_n. On the massless DOFs, from
// the last increments d_n over h_n and d_{n-1} over h_{n-1}: the velocity d_n / h_n + h_n a / 2 and
// the acceleration a = 2 (d_n / h_n - d_{n-1} / h_{n-1}) / (h_n + h_{n-1}) at t_n, so
// u1 = u_n + dt d_n / h_n + dt (h_n + dt) a / 2 (a = 0 at the second step: linear).
void NewmarkStepper::startIterate(double dt) {
  u1_->update(1.0, *uTilde_, scheme_.beta() * dt * dt, *a_, 0.0);
  if (massless_.empty() || !(lastStep_ > 0.0)) return;
  auto u1 = u1_->getDataNonConst();
  auto un = u_->getData();
  auto d1 = lastIncrement_->getData();
  auto d0 = previousIncrement_->getData();
  const double h1 = lastStep_, h0 = previousStep_, curvature = 0.5 * dt * (h1 + dt);
  for (size_t i = 0; i < massless_.size(); ++i) {
    if (!massless_[i]) continue;
    const double a = h0 > 0.0 ? 2.0 * (d1[i] / h1 - d0[i] / h0) / (h1 + h0) : 0.0;
    u1[i] = un[i] + dt * d1[i] / h1 + curvature * a;
  }
}

// The converged attempt that reached t over dt: n+1 becomes n.
void NewmarkStepper::acceptAttempt(double t, double dt) {
  if (!massless_.empty()) {
    std::swap(previousIncrement_, lastIncrement_);
    previousStep_ = lastStep_;
    lastIncrement_->update(1.0, *u1_, -1.0, *u_, 0.0);
    lastStep_ = dt;
  }
  std::swap(u_, u1_);
  std::swap(v_, v1_);
  std::swap(a_, a1_);
  const SecondOrderOperator::CorrectedFields corrected = op_.correctVelocity(*v_, *a_);
  op_.commitMotion(*u_);
  op_.commit();
  std::swap(Ma0_, Ma1_);  // M a and F of the converged u (zero-weighted when alpha is 0)
  if (corrected.acceleration && scheme_.alphaM() != 0.0) op_.applyMass(*a_, *Ma0_);
  if (scheme_.alphaF() != 0.0 && (op_.forcesVaryInTime() || corrected.forces))
    op_.applyForces(*u_, *v_, t, *F0_);  // at t itself (t + h can differ by round-off)
  else
    std::swap(F0_, F1_);
}

// Attempts from s.t, cut on failure, until one converges. A whole nominal step uses dt
// itself (not target - t, which differs by round-off and would change the effective matrix's
// key); after a cut, the cut length goes on until the rest of the nominal step is shorter.
Advance NewmarkStepper::advance(const NominalStep& s, StepControl& c, TransientSummary& sum) {
  double& h = c.h;
  for (;;) {
    const bool finalSub = h >= s.target - s.t - 1e-9 * s.dt;
    if (finalSub) h = std::abs(s.target - s.t - s.dt) <= 1e-9 * s.dt ? s.dt : s.target - s.t;
    NewtonOutcome out = attempt(s.t, h);
    countIterations(out, sum);
    if (out.converged) {  // converged inside the model's domain? (an element inverted at a corner)
      const std::string invalid = checkValidity(*u1_, s.t + h);
      if (!invalid.empty()) out.converged = false, out.message = invalid;
    }
    if (!out.converged) {
      rejectAttempt(s.t, h, c.cuts, out, sum);
      ++c.cuts;
      h *= s_.cutFactor;
      continue;
    }
    Advance a;
    a.time = finalSub ? s.target : s.t + h;
    a.dt = h;
    a.newton = out;
    acceptAttempt(a.time, h);
    return a;
  }
}

}  // namespace choc
