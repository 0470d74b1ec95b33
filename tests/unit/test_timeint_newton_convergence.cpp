// Newton's acceptance tests (timeint/NewtonActiveSet) on a one-DOF static problem
// k u + k3 u^3 = f: the 'residual and increment' test confirms a correction with a second
// solve; 'residual' never does; 'auto' skips it exactly when the operator declares the pass
// linear (SecondOrderOperator::linearWithinPass), so a nonlinear operator keeps the full test.
// With the adaptive linear tolerance (inexact Newton), each correction asks the operator for a
// solve only as exact as the residual test needs; the spring then solves to exactly that
// relative residual, as a Krylov solver stopping there could. A spring whose corrections
// contract the error by a fixed factor (a stale tangent) shows the increment test bounding the
// iterate's error, not just the last correction; one against a stop (a contact status) shows
// the status updated after each correction (semi-smooth) and after converged solves ending on
// the same root. A saturating force (tanh, the smooth shape of a perfectly plastic bar) from a
// point on its plateau: full corrections run away, the line search brings Newton to the root,
// and 'auto' searches exactly where the operator declares kinks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "timeint/NewtonActiveSet.hpp"

namespace choc {
namespace {

class Spring : public SecondOrderOperator {
 public:
  Spring(double k, double k3, double f, bool declaredLinear) : k_(k), k3_(k3), f_(f), linear_(declaredLinear) {
    RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    map_ = rcp(new Map(1, 0, self));
  }
  RCP<const Map> map() const override { return map_; }
  void applyMass(const Vector&, Vector& out) override { set(out, 0.0); }
  void applyForces(const Vector& u, const Vector&, double, Vector& out) override {
    const double x = get(u);
    set(out, k_ * x + k3_ * x * x * x - f_ + (closed_ ? stop * (x - gap) : 0.0));
  }
  double addConstraintForces(const Vector&, const Vector&, Vector&) override { return 0.0; }
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u, const Vector& r,
                                   Vector& du) override {
    const double x = get(u);
    // A solve to the relative residual asked (exact when none is): du = (1 - eta) du_exact.
    const double tangent = k_ + 3 * k3_ * x * x + (closed_ ? stop : 0.0);
    set(du, -(1.0 - relax_) * (1.0 - contraction) * get(r) / (c.cd * tangent));
    asked.push_back(relax_);
    relax_ = 0.0;
    CorrectionStatus s;
    s.ok = true;
    return s;
  }
  // A stop at u = gap of stiffness `stop`: closed while u > gap (0: none).
  ConstraintUpdate updateConstraints(const Vector& u) override {
    ConstraintUpdate up;
    const bool closed = stop > 0.0 && get(u) > gap;
    up.changed = closed != closed_;
    closed_ = closed;
    ++statusEvaluations;
    return up;
  }
  bool linearWithinPass() const override { return linear_; }
  void relaxNextCorrection(double relative) override { relax_ = relative; }
  std::vector<double> asked;  // the relative tolerance each correction was given (0: exact)
  double contraction = 0.0;   // each correction leaves this fraction of the error (0: Newton)
  double stop = 0.0, gap = 0.0;
  int statusEvaluations = 0;
  static double get(const Vector& x) { return x.getData()[0]; }
  static void set(Vector& x, double v) { x.getDataNonConst()[0] = v; }

 private:
  double k_, k3_, f_;
  bool linear_;
  double relax_ = 0.0;
  bool closed_ = false;
  RCP<const Map> map_;
};

struct Solved {
  NewtonOutcome out;
  double u = 0.0;
};

Solved solve(Spring& op, Convergence c, bool adaptive = false, double tolerance = 1e-8) {
  NewtonSettings s;
  s.convergence = c;
  s.adaptiveLinearTolerance = adaptive;
  s.residualTolerance = tolerance;
  Vector u(op.map());
  Solved r;
  r.out = solveStatic(op, u, 0.0, s);
  r.u = Spring::get(u);
  return r;
}

// Solves the spring from u = start with a residual of reference f and round-off floor
// `floor` (as a transient step gives them), plus a constraint row's residual `constraint`
// that the first correction satisfies (violated at the predictor only).
template <class Operator>
Solved solveFrom(Operator& op, const NewtonSettings& s, double start, double f, double floor,
                 double constraint = 0.0) {
  Vector u(op.map()), dummy(op.map());
  Spring::set(u, start);
  auto residual = [&](const Vector& x, Vector& r) {
    op.applyForces(x, dummy, 0.0, r);
    ResidualNorms n;
    n.constraintResidual = op.asked.empty() ? constraint : 0.0;
    n.residual = std::hypot(Spring::get(r), n.constraintResidual);
    n.reference = f;
    n.roundoff = floor;
    n.incrementScale = n.solutionNorm = std::abs(Spring::get(x));
    return n;
  };
  EffectiveCoefficients c;
  c.cd = 1.0;
  Solved out;
  out.out = solveNewtonActiveSet(op, c, residual, u, s);
  out.u = Spring::get(u);
  return out;
}

TEST(NewtonConvergence, ALinearPassTakesOneCorrectionUnlessTheIncrementIsRequired) {
  const double k = 3e7, f = 1.2e4;
  Spring op(k, 0.0, f, true);
  const Solved both = solve(op, Convergence::ResidualAndIncrement);
  const Solved residual = solve(op, Convergence::Residual);
  const Solved automatic = solve(op, Convergence::Auto);
  for (const Solved* s : {&both, &residual, &automatic}) {
    ASSERT_TRUE(s->out.converged) << s->out.message;
    EXPECT_NEAR(s->u, f / k, 1e-14 * f / k);
  }
  EXPECT_EQ(both.out.iterations, 2);  // the second correction only confirms the first
  EXPECT_EQ(residual.out.iterations, 1);
  EXPECT_EQ(automatic.out.iterations, 1);
}

// A hardening spring (k3 u^3 = k u at the solution): Newton converges quadratically. 'auto'
// must not trust a small residual here; it takes exactly the corrections of the full test
// and ends on the same iterate.
TEST(NewtonConvergence, AutoKeepsTheIncrementTestWhenThePassIsNonlinear) {
  const double k = 1.0, k3 = 1.0, f = 2.0;  // solution u = 1
  Spring op(k, k3, f, false);
  const Solved both = solve(op, Convergence::ResidualAndIncrement);
  const Solved automatic = solve(op, Convergence::Auto);
  const Solved residual = solve(op, Convergence::Residual);
  ASSERT_TRUE(both.out.converged) << both.out.message;
  ASSERT_TRUE(automatic.out.converged) << automatic.out.message;
  ASSERT_TRUE(residual.out.converged) << residual.out.message;
  EXPECT_EQ(automatic.out.iterations, both.out.iterations);
  EXPECT_EQ(automatic.u, both.u);
  EXPECT_NEAR(both.u, 1.0, 1e-12);
  // The residual test alone stops one correction earlier, with the last increment unconfirmed.
  EXPECT_EQ(residual.out.iterations + 1, both.out.iterations);
  // Declared linear, the same nonlinear spring would be accepted as soon as the residual is
  // small: that is what the declaration promises to be safe, so it must be truthful.
  Spring lying(k, k3, f, true);
  EXPECT_EQ(solve(lying, Convergence::Auto).out.iterations, residual.out.iterations);
}

// A linear pass: the one correction is asked for a tenth of the residual test's allowance,
// 0.1 * tol * reference / ||R|| (reference and ||R|| both f at the predictor u = 0), never a
// relative residual above 0.1; it is accepted at once and its residual meets the test.
TEST(NewtonConvergence, AdaptiveLinearToleranceAsksWhatTheResidualTestNeeds) {
  const double k = 3e7, f = 1.2e4;
  for (double tol : {1e-8, 1e-3, 10.0}) {
    Spring op(k, 0.0, f, true);
    const Solved s = solve(op, Convergence::Auto, true, tol);
    ASSERT_TRUE(s.out.converged) << s.out.message;
    EXPECT_EQ(s.out.iterations, 1);
    ASSERT_EQ(op.asked.size(), 1u);
    EXPECT_DOUBLE_EQ(op.asked[0], std::min(0.1, 0.1 * tol)) << tol;
    EXPECT_LE(std::abs(k * s.u - f), (std::min(0.1, 0.1 * tol) + 1e-15) * f) << tol;  // + round-off of k u - f
  }
  // Off: every correction exact, nothing asked.
  Spring fixed(k, 0.0, f, true);
  ASSERT_TRUE(solve(fixed, Convergence::Auto, false).out.converged);
  ASSERT_EQ(fixed.asked.size(), 1u);
  EXPECT_EQ(fixed.asked[0], 0.0);
}

// At the round-off floor the residual test allows 1e-12 of the floor, and the correction asks
// for a tenth of that: a residual already near the floor (a body in rigid motion, where the
// reference is small and the residual cannot be computed more exactly) is not chased below
// what can be measured. Here the floor allows 1e-8 against the reference's 1.2e-10, so the
// correction asks 0.1 * 1e-8 / 1e-7 = 0.01 (1.2e-4 from the reference alone) and is accepted.
TEST(NewtonConvergence, AdaptiveLinearToleranceAimsAtTheRoundoffFloorWhenItIsHigher) {
  const double k = 3e7, f = 1.2e4, r0 = 1e-7, floor = 1e4, tol = 1e-14;
  Spring op(k, 0.0, f, true);
  NewtonSettings s;
  s.convergence = Convergence::Auto;
  s.adaptiveLinearTolerance = true;
  s.residualTolerance = tol;
  const NewtonOutcome out = solveFrom(op, s, (f + r0) / k, f, floor).out;
  ASSERT_TRUE(out.converged) << out.message;
  EXPECT_EQ(out.iterations, 1);
  ASSERT_EQ(op.asked.size(), 1u);
  const double r = std::abs(k * ((f + r0) / k) - f);  // the start's residual as computed
  EXPECT_DOUBLE_EQ(op.asked[0], 0.1 * 1e-12 * floor / r);
  EXPECT_GT(op.asked[0], 0.1 * tol * f / r * 10);  // well above what the reference alone asks
}

// A predictor whose residual is already at its round-off floor (a body in free flight) is
// accepted without a correction where the residual test decides alone (a linear pass under
// 'auto', or 'residual'); the increment test still asks for one, and so does a declared
// nonlinear pass or a violated constraint row (a gap, which the floor's forces do not
// measure). Just above the floor (and above tol * reference) the predictor is corrected.
TEST(NewtonConvergence, APredictorAtItsRoundoffFloorIsAcceptedInALinearPass) {
  const double k = 3e7, f = 1.2e4, floor = 1e4, tol = 1e-14;
  struct Case {
    Convergence convergence;
    bool declaredLinear;
    double r0;  // the predictor's residual
    int corrections;
    double constraint = 0.0;  // the predictor's constraint rows' residual
  };
  const double atFloor = 0.5e-12 * floor, aboveFloor = 2e-12 * floor;
  for (const Case& cs : {Case{Convergence::Auto, true, atFloor, 0}, Case{Convergence::Residual, false, atFloor, 0},
                         Case{Convergence::Auto, false, atFloor, 1},
                         Case{Convergence::ResidualAndIncrement, true, atFloor, 1},
                         Case{Convergence::Auto, true, aboveFloor, 1},
                         Case{Convergence::Auto, true, atFloor, 1, 1e-9}}) {
    Spring op(k, 0.0, f, cs.declaredLinear);
    NewtonSettings s;
    s.convergence = cs.convergence;
    s.residualTolerance = tol;
    const Solved run = solveFrom(op, s, (f + cs.r0) / k, f, floor, cs.constraint);
    ASSERT_TRUE(run.out.converged) << run.out.message;
    EXPECT_EQ(run.out.iterations, cs.corrections) << int(cs.convergence) << " " << cs.declaredLinear << " " << cs.r0;
    if (cs.corrections == 0) {
      EXPECT_EQ(run.u, (f + cs.r0) / k);  // the predictor, untouched
    }
  }
}

// A nonlinear pass with inexact corrections: the acceptance tests are unchanged (residual and
// increment), so it converges to the same root within them, each correction asked for less as
// the residual falls.
TEST(NewtonConvergence, AdaptiveLinearToleranceKeepsTheTestsOfANonlinearPass) {
  const double k = 1.0, k3 = 1.0, f = 2.0;  // solution u = 1
  Spring op(k, k3, f, false);
  const Solved s = solve(op, Convergence::Auto, true);
  ASSERT_TRUE(s.out.converged) << s.out.message;
  EXPECT_NEAR(s.u, 1.0, 1e-8);
  EXPECT_LE(std::abs(k * s.u + k3 * s.u * s.u * s.u - f), 1e-8 * f);
  ASSERT_GE(op.asked.size(), 2u);
  for (size_t i = 0; i < op.asked.size(); ++i) {
    EXPECT_GT(op.asked[i], 0.0);
    EXPECT_LE(op.asked[i], 0.1);
    if (i > 0) {
      EXPECT_GE(op.asked[i], op.asked[i - 1]);  // a smaller residual asks for less
    }
  }
}

// Corrections that leave a fixed fraction theta of the error (a stale tangent: linear
// convergence). The last correction alone understates the error by theta / (1 - theta); the
// increment test bounds the error itself, so the accepted iterate is within the increment
// tolerance of the root (here 9 times outside it at theta = 0.9 had the last correction
// decided). The residual test is made loose so that the increment test decides.
TEST(NewtonConvergence, TheIncrementTestBoundsTheErrorOfALinearlyConvergingIterate) {
  const double k = 3e7, f = 1.2e4, root = f / k, tol = 1e-6;
  for (double theta : {0.1, 0.5, 0.9}) {
    Spring op(k, 0.0, f, false);
    op.contraction = theta;
    NewtonSettings s;
    s.convergence = Convergence::ResidualAndIncrement;
    s.residualTolerance = 1.0;
    s.incrementTolerance = tol;
    s.maxIterations = 400;
    Vector u(op.map());
    const NewtonOutcome out = solveStatic(op, u, 0.0, s);
    ASSERT_TRUE(out.converged) << out.message;
    EXPECT_LE(std::abs(Spring::get(u) - root), tol * root) << theta;
  }
}

// A quadratically converging iterate is accepted without the correction that would only
// confirm it. From 1.01: |du_1| = 9.9e-3, |du_2| = 7.4e-5 (above the tolerance 1e-6, but
// theta = 7.5e-3 bounds the error by 5.6e-7), and the residual after it is 1.7e-8: two
// corrections, where the last correction's test would ask for a third (|du_3| = 4.1e-9).
TEST(NewtonConvergence, AQuadraticallyConvergedIterateNeedsNoConfirmingCorrection) {
  const double k = 1.0, k3 = 1.0, f = 2.0;  // root u = 1
  Spring op(k, k3, f, false);
  NewtonSettings s;
  s.convergence = Convergence::ResidualAndIncrement;
  s.residualTolerance = 1e-6;
  s.incrementTolerance = 1e-6;
  const Solved run = solveFrom(op, s, 1.01, f, 0.0);
  ASSERT_TRUE(run.out.converged) << run.out.message;
  EXPECT_EQ(run.out.iterations, 2);
  EXPECT_NEAR(run.u, 1.0, 1e-6);
}

// A hardening spring that runs into a stop (closed beyond u = gap): the status updated after
// each correction and after converged solves end on the same root, with the stop closed, and
// the semi-smooth walk takes fewer corrections (no converged solve on the wrong status).
TEST(NewtonConvergence, StatusEachCorrectionEndsOnTheSameRootInFewerCorrections) {
  const double k = 1.0, k3 = 1.0, f = 2.0, stop = 50.0, gap = 0.5;
  // Root with the stop closed: u + u^3 + 50 (u - 0.5) = 2, u = 0.5228...
  Solved runs[2];
  for (int each = 0; each < 2; ++each) {
    Spring op(k, k3, f, false);
    op.stop = stop;
    op.gap = gap;
    NewtonSettings s;
    s.convergence = Convergence::ResidualAndIncrement;
    s.statusTiming = each == 1 ? StatusTiming::EachCorrection : StatusTiming::ConvergedSolve;
    runs[each] = solveFrom(op, s, 0.0, f, 0.0);
    ASSERT_TRUE(runs[each].out.converged) << runs[each].out.message;
    const double u = runs[each].u;
    EXPECT_GT(u, gap);
    EXPECT_NEAR(u + u * u * u + stop * (u - gap), f, 1e-7 * f);
    EXPECT_EQ(runs[each].out.activeSetIterations, 2);  // one change of status: open, then closed
  }
  EXPECT_NEAR(runs[0].u, runs[1].u, 1e-8);
  EXPECT_LT(runs[1].out.iterations, runs[0].out.iterations);
}

// f(u) = F tanh(u / u0) = P: Newton from u = 3 u0, where the tangent is 1 % of its start, jumps
// to about -47 u0 and on to ever larger |u| (divergent from beyond about 1.09 u0 for P = 0); halving
// the corrections that do not decrease |R| reaches the root u0 artanh(P / F).
class Saturating : public SecondOrderOperator {
 public:
  explicit Saturating(bool kinks) : kinks_(kinks) {
    RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    map_ = rcp(new Map(1, 0, self));
  }
  RCP<const Map> map() const override { return map_; }
  void applyMass(const Vector&, Vector& out) override { Spring::set(out, 0.0); }
  void applyForces(const Vector& u, const Vector&, double, Vector& out) override {
    Spring::set(out, F * std::tanh(Spring::get(u) / u0) - P);
  }
  double addConstraintForces(const Vector&, const Vector&, Vector&) override { return 0.0; }
  CorrectionStatus solveCorrection(const EffectiveCoefficients&, const Vector& u, const Vector& r,
                                   Vector& du) override {
    const double c = std::cosh(Spring::get(u) / u0);
    Spring::set(du, -Spring::get(r) / (F / (u0 * c * c)));
    CorrectionStatus s;
    s.ok = std::isfinite(Spring::get(du));
    return s;
  }
  ConstraintUpdate updateConstraints(const Vector&) override { return {}; }
  bool residualHasKinks() const override { return kinks_; }
  std::vector<double> asked;  // none (solveFrom's constraint row is the predictor's only)
  static constexpr double F = 2.0, u0 = 1e-3, P = 1.0;

 private:
  bool kinks_;
  RCP<const Map> map_;
};

Solved solveSaturating(bool kinks, LineSearch search) {
  Saturating op(kinks);
  NewtonSettings s;
  s.lineSearch = search;
  s.maxIterations = 30;
  return solveFrom(op, s, 3 * Saturating::u0, Saturating::P, 0.0);
}

TEST(NewtonConvergence, TheLineSearchBringsASaturatingForceToItsRoot) {
  const double root = Saturating::u0 * std::atanh(Saturating::P / Saturating::F);
  const Solved whole = solveSaturating(true, LineSearch::Off);
  EXPECT_FALSE(whole.out.converged);  // full corrections run away from the plateau
  EXPECT_EQ(whole.out.lineSearchHalvings, 0);
  for (const bool kinks : {true, false}) {
    const Solved searched = solveSaturating(kinks, kinks ? LineSearch::Auto : LineSearch::On);
    ASSERT_TRUE(searched.out.converged) << searched.out.message;
    // The residual test's 1e-8 P over the slope at the root, F / (u0 cosh^2) = 1,500 P / u0: the
    // root to 6.7e-12 = 1.2e-8 of it.
    EXPECT_NEAR(searched.u, root, 2e-8 * root);
    EXPECT_GT(searched.out.lineSearchHalvings, 0);
  }
  // 'auto' takes whole corrections where the operator declares no kinks.
  EXPECT_EQ(solveSaturating(false, LineSearch::Auto).out.lineSearchHalvings, 0);
}

}  // namespace
}  // namespace choc
