// Newton iterations on R(u) = 0 with an active set of constraints (contact statuses). The
// status is re-evaluated at an iterate the tests accept, and the solve goes on from it while
// the status changes (on any rank); with NewtonSettings::statusEachCorrection also after every
// correction (semi-smooth Newton: a status change starts a new pass at once instead of after a
// converged solve). Convergence of Newton needs both
//   ||R|| <= residualTolerance * reference   (reference: largest of the force terms' norms),
//            or ||R|| <= 1e-12 * (round-off floor of the system, see ResidualNorms)
//   the iterate's error within max(incrementTolerance * incrementScale, 1e-13 ||u||): its
//   bound from the contraction of the last two corrections, theta / (1 - theta) ||du_k|| with
//   theta = ||du_k|| / ||du_k-1|| < 1 (Deuflhard's a posteriori estimate: a quadratically
//   converging iterate needs no correction to confirm it, a slowly contracting one is held to
//   its error), else (one correction, or no contraction) the last correction ||du_k||
//   (see ResidualNorms), unless the settings' Convergence waives it: the residual test alone
//   then accepts any iterate after the first correction, which saves the solve that only
//   confirms a converged one (the predictor itself is accepted on its residual only when that
//   residual is at its round-off floor and no constraint row is violated: a body in free
//   flight, where any correction would move u by round-off). Convergence::Auto waives it exactly in
//   the passes the operator declares linear (SecondOrderOperator::linearWithinPass: one
//   exact correction solves them, so its residual is the whole test), and keeps it for
//   nonlinear ones (friction, shock links), whose residual can be small while u still moves.
// Failure (iterations exhausted, a failed linear solve, a non-finite value) is returned,
// never thrown, so that a step controller can react.
#pragma once
#include <functional>
#include <string>

#include "timeint/SecondOrderOperator.hpp"

namespace choc {

// Which tests accept an iterate: both, the residual alone, or the residual alone in the passes
// that are linear (the default of the inputs).
enum class Convergence { ResidualAndIncrement, Residual, Auto };
// When the constraint status is re-evaluated: after every correction, after a converged solve,
// or 'auto': after every correction unless the operator's residual has kinks in u
// (SecondOrderOperator::residualHasKinks: plastic return maps), then after converged solves.
enum class StatusTiming { EachCorrection, ConvergedSolve, Auto };
// Whether a correction that does not decrease the residual is shortened (backtracking line
// search, NewtonActiveSet.cpp searchLine): always, never, or 'auto': where the operator's
// residual has kinks in u.
enum class LineSearch { Auto, On, Off };

struct NewtonSettings {
  double residualTolerance = 1e-8;
  double incrementTolerance = 1e-8;
  Convergence convergence = Convergence::ResidualAndIncrement;
  int maxIterations = 10;
  int maxActiveSetIterations = 20;
  // Semi-smooth Newton (EachCorrection): the constraint status re-evaluated after every
  // correction, a change starting a new pass at once; ConvergedSolve: only at an iterate the
  // tests accept (a fixed point of converged Newton solves). Both end at an accepted iterate
  // whose status holds. The input's 'Contact/Status Update' (default 'auto').
  StatusTiming statusTiming = StatusTiming::EachCorrection;
  // The input's 'Newton/Line Search' (default 'auto').
  LineSearch lineSearch = LineSearch::Auto;
  // Inexact Newton: each correction's iterative linear solve may stop once the linear residual
  // is a tenth of what the residual test allows, kForcing * max(residualTolerance * reference,
  // 1e-12 * roundoff) (the test accepts a residual at its round-off floor too; at most a
  // relative kMaxForcing of the Newton residual it starts from); the acceptance tests above
  // are unchanged. Off: every solve to the linear solver's own tolerance.
  bool adaptiveLinearTolerance = false;
  static constexpr double kForcing = 0.1, kMaxForcing = 0.1;
  // 'Massless Start' = 'extrapolated': the massless DOFs (redistributed contact mass) start each
  // step's Newton from their last increments extrapolated (NewmarkStepper::extrapolateMassless).
  bool extrapolateMassless = true;
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;           // Newton corrections (linear solves), all active-set passes
  int activeSetIterations = 0;  // Newton solves (status evaluations)
  int refactorizations = 0;
  int krylovIterations = 0;
  int backtracks = 0;  // halvings of corrections that had inverted an element
  int lineSearchHalvings = 0;  // halvings of corrections that did not decrease the residual
  double residual = 0.0, reference = 0.0;
  std::string message;  // why it failed
};

// r = R(u) including constraint forces; returns {||r|| including the constraint equations,
// reference force norm}.
struct ResidualNorms {
  double residual = 0.0, reference = 0.0;
  // The constraint rows' part of the residual (gaps of active multipliers, multipliers of
  // inactive ones): measured in their own units, not against the round-off floor's forces.
  double constraintResidual = 0.0;
  // Round-off floor: the size of the largest terms of the residual at u (||c_a M u||,
  // || |K| |u| ||); a residual below 1e-12 of it is at round-off, whatever the reference
  // (rigid motion, loads that cancel).
  double roundoff = 0.0;
  // Size of the solution's change that increments are measured against: ||u_{n+1} - u_n||
  // for a step, ||u|| for a static solve.
  double incrementScale = 0.0;
  double solutionNorm = 0.0;  // ||u||: increments below 1e-13 of it are round-off
};
using ResidualFunction = std::function<ResidualNorms(const Vector& u, Vector& r)>;

NewtonOutcome solveNewtonActiveSet(SecondOrderOperator& op, const EffectiveCoefficients& c,
                                   const ResidualFunction& residual, Vector& u,
                                   const NewtonSettings& s);

// Static equilibrium F(u, 0, t) + f_c(u) = 0 (W = K + constraint block), from u.
NewtonOutcome solveStatic(SecondOrderOperator& op, Vector& u, double t, const NewtonSettings& s);

}  // namespace choc
