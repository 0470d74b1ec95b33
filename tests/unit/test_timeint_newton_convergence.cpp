// Newton's acceptance tests (timeint/NewtonActiveSet) on a one-DOF static problem
// k u + k3 u^3 = f: the 'residual and increment' test confirms a correction with a second
// solve; 'residual' never does; 'auto' skips it exactly when the operator declares the pass
// linear (SecondOrderOperator::linearWithinPass), so a nonlinear operator keeps the full test.
#include <gtest/gtest.h>

#include <cmath>

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
    set(out, k_ * x + k3_ * x * x * x - f_);
  }
  double addConstraintForces(const Vector&, const Vector&, Vector&) override { return 0.0; }
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u, const Vector& r,
                                   Vector& du) override {
    const double x = get(u);
    set(du, -get(r) / (c.cd * (k_ + 3 * k3_ * x * x)));
    CorrectionStatus s;
    s.ok = true;
    return s;
  }
  ConstraintUpdate updateConstraints(const Vector&) override { return {}; }
  bool linearWithinPass() const override { return linear_; }
  static double get(const Vector& x) { return x.getData()[0]; }
  static void set(Vector& x, double v) { x.getDataNonConst()[0] = v; }

 private:
  double k_, k3_, f_;
  bool linear_;
  RCP<const Map> map_;
};

struct Solved {
  NewtonOutcome out;
  double u = 0.0;
};

Solved solve(Spring& op, Convergence c) {
  NewtonSettings s;
  s.convergence = c;
  Vector u(op.map());
  Solved r;
  r.out = solveStatic(op, u, 0.0, s);
  r.u = Spring::get(u);
  return r;
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

}  // namespace
}  // namespace choc
