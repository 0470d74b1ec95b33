#include "timeint/NewtonActiveSet.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {

// The last two corrections' norms (-1: none yet in this pass).
struct Increments {
  double last = -1.0, previous = -1.0;
  void push(double d) {
    previous = last;
    last = d;
  }
};

// Whether the increment test accepts the iterate: its error bounded within the tolerance by
// the contraction of the last two corrections (theta = |du_k| / |du_k-1| < 1:
// |u* - u_k| <= theta / (1 - theta) |du_k|, Deuflhard), or, with no contraction to measure (one
// correction, or none), the last correction within it.
bool incrementWithin(const Increments& inc, double tolerance) {
  if (inc.last < 0) return false;
  const double theta = inc.previous > 0 ? inc.last / inc.previous : 1.0;
  if (theta < 1.0) return theta / (1.0 - theta) * inc.last <= tolerance;
  return inc.last <= tolerance;
}

// Whether Newton stops at this iterate: the residual within what its test allows, and the
// increment small enough (or the test of the increment waived).
bool iterateAccepted(const ResidualNorms& n, double allowed, const Increments& inc, bool requireIncrement,
                     const NewtonSettings& s) {
  const double lastIncrement = inc.last;
  const bool resOk = n.residual <= allowed;
  const bool incOk =
      incrementWithin(inc, std::max(s.incrementTolerance * n.incrementScale, 1e-13 * n.solutionNorm));
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
         (state.empty() ? "" : "; " + state) + ")" +
         (op.residualHasKinks() && maxIterations < 30
              ? "; a plastic model on a yielding contact zone can need 10 to 35 corrections per "
                "step: if the residual was still falling, raise 'Newton/Maximum Iterations' to 30"
              : "");
}

// The walk of one solve: the pass (constraint status) it is in, its corrections, and whether
// the status was evaluated at the current iterate.
struct ActiveSetWalk {
  Increments increments;
  int correctionsInPass = 0;
  bool statusCurrent = false;
  bool corrected = false;  // u is the last correction's iterate, not yet evaluated
  std::string lastSummary;
};

// The last correction halved: u back by half of du, du and its norm halved.
void halveCorrection(Vector& u, Vector& du, ActiveSetWalk& w) {
  u.update(-0.5, du, 1.0);
  du.scale(0.5);
  w.increments.last *= 0.5;
  w.statusCurrent = false;
}

// The residual at u. Where a correction has carried u outside the model's domain (an inverted
// element: InadmissibleState), the correction is halved, up to kMaxBacktracks times, so that
// Newton goes on from inside it; at the predictor, or beyond the last halving, the state is
// rethrown and the attempt fails (the stepper then cuts dt).
constexpr int kMaxBacktracks = 8;

ResidualNorms evaluate(const ResidualFunction& residual, Vector& u, Vector& r, Vector& du, ActiveSetWalk& w,
                       NewtonOutcome& out) {
  for (int halvings = 0;; ++halvings) {
    try {
      const ResidualNorms n = residual(u, r);
      w.corrected = false;
      return n;
    } catch (const InadmissibleState&) {
      if (!w.corrected || halvings == kMaxBacktracks) throw;
      halveCorrection(u, du, w);
      ++out.backtracks;
    }
  }
}

// Backtracking line search (Armijo on the residual norm) for operators whose residual has kinks
// (plastic return maps, SecondOrderOperator::residualHasKinks): the residual at the corrected u,
// and while it is not below (1 - 1e-4 s) of the residual `start` the correction began from
// (s: the fraction of the correction kept), the correction is halved (u, du, the operator's
// extra unknowns), at most kMaxLineSearch times; the last iterate is kept whatever, and Newton
// goes on from it. A full Newton correction that overshoots a point's change between elastic and
// plastic response can otherwise send the iterates back and forth, or far away, at a
// consistent tangent.
constexpr int kMaxLineSearch = 6;

ResidualNorms searchLine(SecondOrderOperator& op, const ResidualFunction& residual, double start, double allowed,
                         Vector& u, Vector& r, Vector& du, ActiveSetWalk& w, NewtonOutcome& out) {
  double kept = 1.0;
  for (int halvings = 0;; ++halvings) {
    const ResidualNorms n = evaluate(residual, u, r, du, w, out);
    if (!std::isfinite(n.residual) || n.residual <= allowed || n.residual <= (1.0 - 1e-4 * kept) * start ||
        halvings == kMaxLineSearch)
      return n;
    halveCorrection(u, du, w);
    op.scaleLastCorrection(0.5);
    w.corrected = true;  // u is a shortened correction's iterate (evaluate may halve it further)
    kept *= 0.5;
    ++out.lineSearchHalvings;
  }
}

bool searchesLine(const SecondOrderOperator& op, const NewtonSettings& s) {
  return s.lineSearch == LineSearch::On || (s.lineSearch == LineSearch::Auto && op.residualHasKinks());
}

bool statusEachCorrection(const SecondOrderOperator& op, const NewtonSettings& s) {
  return s.statusTiming == StatusTiming::EachCorrection ||
         (s.statusTiming == StatusTiming::Auto && !op.residualHasKinks());
}

// Evaluates the status at u; when it changes, a new pass starts (false: too many passes).
bool evaluateStatus(SecondOrderOperator& op, const Vector& u, const NewtonSettings& s, ActiveSetWalk& w,
                    NewtonOutcome& out) {
  const ConstraintUpdate upd = op.updateConstraints(u);
  w.statusCurrent = true;
  if (!upd.changed) return true;
  w.lastSummary = upd.summary;
  if (out.activeSetIterations >= s.maxActiveSetIterations) {
    out.message = "the active set did not settle in " + std::to_string(s.maxActiveSetIterations) +
                  " iterations (last pass: " + w.lastSummary + ")";
    return false;
  }
  ++out.activeSetIterations;
  w.increments = Increments();
  w.correctionsInPass = 0;
  return true;
}

// One Newton correction of u; false with out.message when it fails.
bool correct(SecondOrderOperator& op, const EffectiveCoefficients& c, const ResidualNorms& n, double allowed,
             const NewtonSettings& s, Vector& u, Vector& r, Vector& du, ActiveSetWalk& w, NewtonOutcome& out) {
  if (s.adaptiveLinearTolerance && n.residual > 0.0)
    op.relaxNextCorrection(std::min(NewtonSettings::kMaxForcing, NewtonSettings::kForcing * allowed / n.residual));
  const CorrectionStatus cs = op.solveCorrection(c, u, r, du);
  ++out.iterations;
  ++w.correctionsInPass;
  out.krylovIterations += cs.iterations;
  if (cs.refactored) ++out.refactorizations;
  if (!cs.ok) {
    out.message = "linear solve failed: " + cs.message;
    return false;
  }
  u.update(1.0, du, 1.0);
  w.increments.push(du.norm2());
  w.statusCurrent = false;
  w.corrected = true;
  if (!std::isfinite(w.increments.last)) {
    out.message = "the Newton correction is not finite";
    return false;
  }
  return true;
}

}  // namespace

NewtonOutcome solveNewtonActiveSet(SecondOrderOperator& op, const EffectiveCoefficients& c,
                                   const ResidualFunction& residual, Vector& u,
                                   const NewtonSettings& s) {
  NewtonOutcome out;
  out.activeSetIterations = 1;
  Vector r(op.map()), du(op.map());
  const bool requireIncrement =
      s.convergence == Convergence::ResidualAndIncrement ||
      (s.convergence == Convergence::Auto && !op.linearWithinPass());
  const bool eachCorrection = statusEachCorrection(op, s);
  ActiveSetWalk w;
  ResidualNorms n;
  bool evaluated = false;  // n and r are those at u (the line search's last evaluation)
  for (;;) {
    if (!evaluated) n = evaluate(residual, u, r, du, w, out);
    evaluated = false;
    out.residual = n.residual;
    out.reference = n.reference;
    if (!std::isfinite(n.residual)) {
      out.message = "the residual is not finite";
      return out;
    }
    // What the residual test allows: the tolerance of the reference, or the round-off floor.
    const double allowed = std::max(s.residualTolerance * n.reference, 1e-12 * n.roundoff);
    if (iterateAccepted(n, allowed, w.increments, requireIncrement, s)) {
      if (w.statusCurrent) {
        out.converged = true;
        return out;
      }
      // The status at the accepted iterate: unchanged, the solve is done; changed, a new pass.
      const int passes = out.activeSetIterations;
      if (!evaluateStatus(op, u, s, w, out)) return out;
      if (out.activeSetIterations == passes) {
        out.converged = true;
        return out;
      }
      continue;
    }
    if (w.correctionsInPass >= s.maxIterations) {
      out.message = notConvergedMessage(op, n, s.maxIterations);
      return out;
    }
    if (!correct(op, c, n, allowed, s, u, r, du, w, out)) return out;
    if (searchesLine(op, s)) {
      n = searchLine(op, residual, n.residual, allowed, u, r, du, w, out);
      evaluated = true;
    }
    const int passes = out.activeSetIterations;
    if (eachCorrection && !evaluateStatus(op, u, s, w, out)) return out;
    if (out.activeSetIterations != passes) evaluated = false;  // another status: another residual
  }
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
