// A free rigid body spinning near its intermediate axis (shared/BENCHMARKS.md section 17): the
// two rotation steps of src/rigid/RotationStep.hpp against Euler's equations.
//   - Exact: the kinetic energy E and |L| constant; the body flips with the period
//     T = 4 K(k) / nu, nu = sqrt((I3 - I2)(L^2 - 2 E I1) / (I1 I2 I3)),
//     k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1)) for L^2 > 2 E I2 (Landau and
//     Lifshitz, Mechanics, section 37), K by the arithmetic-geometric mean.
//   - The body-frame angular velocity against an independent integration of Euler's
//     equations (classical Runge-Kutta at 1/50 of the finest step: its error is 1e-10 of the
//     motion, far below the schemes').
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "rigid/RotationStep.hpp"

namespace choc {
namespace {

const Vec3 kInertia = {2.0, 3.0, 4.0};        // I1 < I2 < I3 [kg m^2]
const Vec3 kOmega0 = {0.05, 1.0, 0.05};       // mostly about axis 2 [rad/s]

double energyOf(const Vec3& w) {
  return 0.5 * (kInertia[0] * w[0] * w[0] + kInertia[1] * w[1] * w[1] + kInertia[2] * w[2] * w[2]);
}
double momentumSquared(const Vec3& w) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += kInertia[i] * kInertia[i] * w[i] * w[i];
  return s;
}

// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double completeEllipticK(double k2) {
  double a = 1.0, b = std::sqrt(1.0 - k2);
  for (int i = 0; i < 60 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  return M_PI / (2.0 * a);
}

double closedFormPeriod() {
  const double E = energyOf(kOmega0), L2 = momentumSquared(kOmega0);
  const double I1 = kInertia[0], I2 = kInertia[1], I3 = kInertia[2];
  EXPECT_GT(L2, 2 * E * I2);  // the branch of the formula
  const double nu = std::sqrt((I3 - I2) * (L2 - 2 * E * I1) / (I1 * I2 * I3));
  const double k2 = (I2 - I1) * (2 * E * I3 - L2) / ((I3 - I2) * (L2 - 2 * E * I1));
  return 4.0 * completeEllipticK(k2) / nu;
}

// Euler's equations I w' = (I w) x w in the body frame.
Vec3 eulerRate(const Vec3& w) {
  const Vec3 Iw = {kInertia[0] * w[0], kInertia[1] * w[1], kInertia[2] * w[2]};
  const Vec3 c = cross(Iw, w);
  return {c[0] / kInertia[0], c[1] / kInertia[1], c[2] / kInertia[2]};
}

Vec3 rungeKutta(Vec3 w, double h, int steps) {
  auto add = [](const Vec3& a, const Vec3& b, double f) { return Vec3{a[0] + f * b[0], a[1] + f * b[1], a[2] + f * b[2]}; };
  for (int n = 0; n < steps; ++n) {
    const Vec3 k1 = eulerRate(w), k2 = eulerRate(add(w, k1, h / 2)), k3 = eulerRate(add(w, k2, h / 2)),
               k4 = eulerRate(add(w, k3, h));
    for (int i = 0; i < 3; ++i) w[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return w;
}

struct SpinRun {
  double energyError = 0.0;    // largest |E - E0| / E0
  double momentumError = 0.0;  // largest ||L| - |L0|| / |L0|
  double period = 0.0;         // from the sign changes of the body-frame w2
  double omegaError = 0.0;     // largest |w - w_ref| / |w0| at the checkpoints
};

// The body started in a turned attitude (the frame must not matter), run over two periods.
SpinRun spin(bool implicit, double h, double periods = 2.2) {
  const Matrix33 R0 = rotationFromVector({0.4, -0.3, 1.1});
  RotationState s = stateFromAngularVelocity(kInertia, R0, R0 * kOmega0);
  const double E0 = rotationalEnergy(kInertia, s), L0 = norm(s.momentum);
  const int steps = int(std::lround(periods * closedFormPeriod() / h));
  const int every = int(std::lround(5.0 / h));  // reference checkpoints every 5 s
  const double hRef = h / 50;
  Vec3 wRef = kOmega0;
  SpinRun out;
  std::vector<double> crossings;
  double previous = kOmega0[1];
  for (int n = 1; n <= steps; ++n) {
    if (implicit) {
      const MidpointRotation m = rotateByMidpoint(kInertia, h, s.momentum, s);
      EXPECT_TRUE(m.converged) << m.message;
    } else {
      rotateFreelyBySplitting(kInertia, h, s);
    }
    const Vec3 wb = transpose(s.R) * angularVelocity(kInertia, s);
    out.energyError = std::max(out.energyError, std::abs(rotationalEnergy(kInertia, s) - E0) / E0);
    out.momentumError = std::max(out.momentumError, std::abs(norm(s.momentum) - L0) / L0);
    if ((previous > 0) != (wb[1] > 0)) crossings.push_back(h * (n - 1 + previous / (previous - wb[1])));
    previous = wb[1];
    if (n % every == 0) {
      wRef = rungeKutta(wRef, hRef, every * 50);
      out.omegaError = std::max(out.omegaError, norm(wb - wRef) / norm(kOmega0));
    }
  }
  EXPECT_GE(crossings.size(), 4u);
  if (crossings.size() >= 4) out.period = crossings[3] - crossings[1];  // two half periods
  std::printf("%s h = %.4g s: E %.2e, |L| %.2e, period %.6f s (closed form %.6f), w %.2e\n",
              implicit ? "midpoint" : "splitting", h, out.energyError, out.momentumError, out.period,
              closedFormPeriod(), out.omegaError);
  return out;
}

// The energy-momentum midpoint rule: E and |L| to round-off over two flips, at any step;
// period and motion second order.
TEST(FreeRigidRotation, TheMidpointRuleConservesEnergyAndMomentumAndFlipsAtThePeriod) {
  const double T = closedFormPeriod();
  std::vector<SpinRun> runs;
  for (double h : {0.1, 0.05, 0.025}) runs.push_back(spin(true, h));
  for (const SpinRun& r : runs) {
    EXPECT_LT(r.energyError, 1e-13);   // the Newton tolerance 1e-14 on theta, summed over ~2,000 steps
    EXPECT_LT(r.momentumError, 1e-14);  // pi is not touched: round-off
  }
  const double e0 = std::abs(runs[0].period - T), e1 = std::abs(runs[1].period - T), e2 = std::abs(runs[2].period - T);
  EXPECT_LT(e2 / T, 1e-3) << "period " << runs[2].period << " against " << T;
  EXPECT_NEAR(std::log2(e0 / e1), 2.0, 0.25);  // second order
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.25);
  EXPECT_NEAR(std::log2(runs[0].omegaError / runs[1].omegaError), 2.0, 0.3);
}

// The splitting: |L| to round-off, the energy's oscillation second order in h and without drift
// (its largest over two periods no larger than over the first half period's... times 1.5),
// period and motion second order.
TEST(FreeRigidRotation, TheSplittingConservesMomentumAndTheEnergyToSecondOrder) {
  const double T = closedFormPeriod();
  std::vector<SpinRun> runs;
  for (double h : {0.05, 0.025, 0.0125}) runs.push_back(spin(false, h));
  for (const SpinRun& r : runs) EXPECT_LT(r.momentumError, 1e-14);
  EXPECT_NEAR(std::log2(runs[0].energyError / runs[1].energyError), 2.0, 0.25);
  EXPECT_NEAR(std::log2(runs[1].energyError / runs[2].energyError), 2.0, 0.25);
  const SpinRun longer = spin(false, 0.05, 8.2);  // no drift: four times as long, the same bound
  EXPECT_LT(longer.energyError, 1.5 * runs[0].energyError);
  const double e0 = std::abs(runs[0].period - T), e1 = std::abs(runs[1].period - T), e2 = std::abs(runs[2].period - T);
  EXPECT_LT(e2 / T, 1e-3) << "period " << runs[2].period << " against " << T;
  EXPECT_NEAR(std::log2(e0 / e1), 2.0, 0.25);
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.25);
  EXPECT_NEAR(std::log2(runs[0].omegaError / runs[1].omegaError), 2.0, 0.3);
}

// The midpoint rule's Newton tangent against central differences of its residual (and a
// perturbed tangent caught).
TEST(FreeRigidRotation, TheMidpointTangentIsItsResidualsDerivative) {
  const Vec3 body = {0.3, 2.9, -0.4}, next = {0.5, 2.7, -0.2};
  const double h = 0.2;
  for (const Vec3& theta : {Vec3{0, 0, 0}, Vec3{0.03, 0.21, -0.05}, Vec3{0.6, -1.4, 0.9}}) {
    const Matrix33 T = midpointTangent(kInertia, h, next, theta);
    test::Dense J(3, 3);
    for (int k = 0; k < 9; ++k) J.a[size_t(k)] = T[size_t(k)];
    const test::Residual R = [&](const std::vector<double>& x) {
      const Vec3 g = midpointResidual(kInertia, h, body, next, {x[0], x[1], x[2]});
      return std::vector<double>{g[0], g[1], g[2]};
    };
    const std::vector<double> x = {theta[0], theta[1], theta[2]};
    test::TangentCheckOptions o;
    o.scale = 1.0;  // radians
    EXPECT_TRUE(test::tangentMatches(R, J, x, o)) << "theta " << norm(theta);
    EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), x, o));
  }
}

}  // namespace
}  // namespace choc
