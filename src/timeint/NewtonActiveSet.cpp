#include "timeint/NewtonActiveSet.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>

#include <Tpetra_Vector.hpp>

#include "core/Format.hpp"

namespace choc {

namespace {

// Whether Newton stops at this iterate: the residual within what its test allows, and the
// last increment small enough (or the test of the increment waived).
bool iterateAccepted(const ResidualNorms& n, double allowed, double lastIncrement, bool requireIncrement,
                     const NewtonSettings& s) {
  const double stepNorm = n.incrementScale;
  const bool resOk = n.residual <= allowed;
  const bool incOk = lastIncrement >= 0 &&
                     lastIncrement <= std::max(s.incrementTolerance * stepNorm, 1e-13 * n.solutionNorm);
  // The predictor (no correction yet) is accepted on its residual only when that residual
  // is at its round-off floor in a pass whose residual test decides alone, and no
  // constraint row is violated (a gap is not measured by the floor's forces): any
  // correction would move u by round-off (a body in free flight, whose predictor is exact).
  const bool predictorAtFloor = !requireIncrement && lastIncrement < 0 && n.constraintResidual == 0.0 &&
                                n.residual <= 1e-12 * n.roundoff;
  const bool incrementAccepted = (!requireIncrement && lastIncrement >= 0) || incOk ||
                                 lastIncrement == 0.0 || (lastIncrement < 0 && n.residual == 0.0) ||
                                 predictorAtFloor;
  return resOk && incrementAccepted;
}

std::string notConvergedMessage(const SecondOrderOperator& op, const ResidualNorms& n, int maxIterations) {
  const std::string state = op.constraintState();
  return "Newton did not converge in " + std::to_string(maxIterations) + " iterations (" +
         format("residual %.3e for a reference %.3e", n.residual, n.reference) +
         (state.empty() ? "" : "; " + state) + ")";
}

// Newton iterations with the constraint status frozen (one active-set pass): true when they
// converge, false with out.message when they fail.
bool solveStatusFrozen(SecondOrderOperator& op, const EffectiveCoefficients& c, const ResidualFunction& residual,
                       Vector& u, const NewtonSettings& s, Vector& r, Vector& du, NewtonOutcome& out) {
  const bool requireIncrement =
      s.convergence == Convergence::ResidualAndIncrement ||
      (s.convergence == Convergence::Auto && !op.linearWithinPass());
  double lastIncrement = -1.0;
  for (int it = 0;; ++it) {
    const ResidualNorms n = residual(u, r);
    out.residual = n.residual;
    out.reference = n.reference;
    if (!std::isfinite(n.residual)) {
      out.message = "the residual is not finite";
      return false;
    }
    // What the residual test allows: the tolerance of the reference, or the round-off floor.
    const double allowed = std::max(s.residualTolerance * n.reference, 1e-12 * n.roundoff);
    if (iterateAccepted(n, allowed, lastIncrement, requireIncrement, s)) return true;
    if (it >= s.maxIterations) {
      out.message = notConvergedMessage(op, n, s.maxIterations);
      return false;
    }
    if (s.adaptiveLinearTolerance && n.residual > 0.0)
      op.relaxNextCorrection(std::min(NewtonSettings::kMaxForcing, NewtonSettings::kForcing * allowed / n.residual));
    const CorrectionStatus cs = op.solveCorrection(c, u, r, du);
    ++out.iterations;
    out.krylovIterations += cs.iterations;
    if (cs.refactored) ++out.refactorizations;
    if (!cs.ok) {
      out.message = "linear solve failed: " + cs.message;
      return false;
    }
    u.update(1.0, du, 1.0);
    lastIncrement = du.norm2();
    if (!std::isfinite(lastIncrement)) {
      out.message = "the Newton correction is not finite";
      return false;
    }
  }
}

}  // namespace

NewtonOutcome solveNewtonActiveSet(SecondOrderOperator& op, const EffectiveCoefficients& c,
                                   const ResidualFunction& residual, Vector& u,
                                   const NewtonSettings& s) {
  NewtonOutcome out;
  Vector r(op.map()), du(op.map());
  std::string lastSummary;
  for (int pass = 1; pass <= s.maxActiveSetIterations; ++pass) {
    out.activeSetIterations = pass;
    if (!solveStatusFrozen(op, c, residual, u, s, r, du, out)) return out;
    const ConstraintUpdate upd = op.updateConstraints(u);
    if (!upd.changed) {
      out.converged = true;
      return out;
    }
    lastSummary = upd.summary;
  }
  out.message = "the active set did not settle in " + std::to_string(s.maxActiveSetIterations) +
                " iterations (last pass: " + lastSummary + ")";
  return out;
}

NewtonOutcome solveStatic(SecondOrderOperator& op, Vector& u, double t, const NewtonSettings& s) {
  Vector zero(op.map()), fc(op.map()), load(op.map()), r2(op.map());
  EffectiveCoefficients c;
  c.cd = 1.0;
  op.applyForces(zero, zero, t, load);  // -f_ext(t)
  const double loadNorm = load.norm2();
  auto residual = [&](const Vector& x, Vector& r) {
    op.applyForces(x, zero, t, r);
    fc.putScalar(0.0);
    const double cons = op.addConstraintForces(x, zero, fc);
    ResidualNorms n;
    n.reference = std::max({r.norm2(), fc.norm2(), loadNorm});
    r.update(1.0, fc, 1.0);
    const double rn = r.norm2();
    n.residual = std::sqrt(rn * rn + cons * cons);
    n.constraintResidual = cons;
    op.applyForces(x, zero, t, r2);  // K x - f_ext
    r2.update(-1.0, load, 1.0);       // K x
    n.roundoff = r2.norm2();
    n.incrementScale = x.norm2();
    n.solutionNorm = n.incrementScale;
    return n;
  };
  return solveNewtonActiveSet(op, c, residual, u, s);
}

}  // namespace choc
