// Properties of the exact solution: continuity, velocity = du/dt, impulse, bilateral wave,
// parameter validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "reference/BarImpactExact.hpp"

namespace {

using choc::BarImpactExact;
using choc::BarImpactParameters;

constexpr double kRho = 7800.0, kS = 4e-4, kL = 1.0;

BarImpactParameters bars(double c, double t0, bool bilateral) {
  BarImpactParameters p;
  p.length = kL;
  p.waveSpeed = c;
  p.impedance = kRho * c * kS;
  p.impactVelocity = -1.0;
  p.contactStart = t0;
  p.bilateral = bilateral;
  return p;
}

// The three cases: 1D unilateral, 3D unilateral with approach, 1D bilateral.
std::vector<BarImpactParameters> cases() {
  return {bars(std::sqrt(2e11 / kRho), 0.0, false), bars(5875.097, 1e-5, false),
          bars(std::sqrt(2e11 / kRho), 0.0, true)};
}

std::vector<double> kinks(const BarImpactExact& e) {
  std::vector<double> k;
  for (int i = 0; i <= 8; ++i) k.push_back(e.contactStart() + i * e.transitTime());
  return k;
}

TEST(BarImpactExact, DisplacementIsContinuousAtEveryKink) {
  for (const auto& p : cases()) {
    const BarImpactExact e(p);
    const double eps = 1e-10;
    for (double tk : kinks(e)) {
      if (tk < eps) continue;
      const double jump = e.displacementA(tk + eps) - e.displacementA(tk - eps);
      EXPECT_LE(std::abs(jump), 2.0 * eps * 1.0 + 1e-18) << "kink at " << tk;
    }
  }
}

TEST(BarImpactExact, VelocityIsTheDerivativeOfDisplacement) {
  for (const auto& p : cases()) {
    const BarImpactExact e(p);
    const auto k = kinks(e);
    const double h = 1e-8;
    int tested = 0;
    for (double t = 2e-6; t < 2e-3; t += 3.7e-6) {
      bool nearKink = false;
      for (double tk : k) nearKink = nearKink || std::abs(t - tk) < 2 * h;
      if (nearKink) continue;
      const double fd = (e.displacementA(t + h) - e.displacementA(t - h)) / (2 * h);
      EXPECT_NEAR(fd, e.velocityA(t), 1e-6) << "t = " << t << " bilateral " << p.bilateral;
      ++tested;
    }
    EXPECT_GT(tested, 500);
  }
}

TEST(BarImpactExact, UnilateralPhases) {
  const BarImpactExact e(bars(5000.0, 1e-5, false));  // tau = 4e-4
  EXPECT_DOUBLE_EQ(e.velocityA(0.5e-5), -1.0);
  EXPECT_DOUBLE_EQ(e.contactForce(0.5e-5), 0.0);
  EXPECT_DOUBLE_EQ(e.displacementA(1e-5), -1e-5);  // contact at the gap J0
  EXPECT_DOUBLE_EQ(e.velocityA(1e-5), -0.5);       // right limit at t0
  EXPECT_GT(e.contactForce(1e-5), 0.0);
  EXPECT_DOUBLE_EQ(e.velocityA(1e-5 + 4e-4), 0.5);  // right limit at t0 + tau
  EXPECT_DOUBLE_EQ(e.velocityA(1e-3), 1.0);         // rebound at -v0
  EXPECT_DOUBLE_EQ(e.contactForce(1e-3), 0.0);
  EXPECT_DOUBLE_EQ(e.contactEnd(), 1e-5 + 8e-4);
  EXPECT_DOUBLE_EQ(e.contactForce(e.contactEnd()), 0.0);  // right limit: open
  EXPECT_NEAR(e.displacementA(e.contactEnd()), -1e-5, 1e-18);  // back where contact began
  EXPECT_DOUBLE_EQ(e.period(), 1.6e-3);
}

TEST(BarImpactExact, PeakIsTheLargestDisplacementOfTheFirstContact) {
  for (const auto& p : cases()) {
    const BarImpactExact e(p);
    double maxAbs = 0.0;
    const double end = e.contactStart() + 2 * e.transitTime();
    for (int i = 0; i <= 100000; ++i) maxAbs = std::max(maxAbs, std::abs(e.displacementA(end * i / 100000)));
    EXPECT_LE(maxAbs, e.peakDisplacement() * (1 + 1e-12));
    EXPECT_GE(maxAbs, e.peakDisplacement() * (1 - 1e-4));
    EXPECT_NEAR(e.peakDisplacement(), p.contactStart + kL / p.waveSpeed, 1e-15);
  }
}

// The contact reverses the momentum of bar AB: int F dt = 2 m |v0| with m = rho S L.
TEST(BarImpactExact, ImpulseReversesTheMomentumOfBarAB) {
  for (const auto& p : cases()) {
    if (p.bilateral) continue;
    const BarImpactExact e(p);
    const double m = kRho * kS * kL;
    EXPECT_NEAR(e.contactForceMagnitude() * e.contactDuration(), 2 * m, 1e-12 * m);
    const int n = 200000;
    const double end = e.contactEnd() * 1.25, dt = end / n;
    double impulse = 0.0;
    for (int i = 0; i < n; ++i) impulse += e.contactForce((i + 0.5) * dt) * dt;
    EXPECT_NEAR(impulse, 2 * m * 1.0, 1e-4 * 2 * m);
  }
}

TEST(BarImpactExact, BilateralTriangleWave) {
  const double c = 5000.0;
  const BarImpactExact e(bars(c, 0.0, true));
  const double amp = kL / c, period = 8 * kL / c;
  EXPECT_DOUBLE_EQ(e.period(), period);
  EXPECT_TRUE(std::isinf(e.contactEnd()));
  EXPECT_NEAR(e.displacementA(period / 4), -amp, 1e-18);
  EXPECT_NEAR(e.displacementA(3 * period / 4), amp, 1e-18);
  for (double t = 1e-5; t < 2e-3; t += 7.3e-6) {
    EXPECT_NEAR(e.displacementA(t + period), e.displacementA(t), 1e-17) << t;
    EXPECT_NEAR(e.displacementA(t + 2 * period), e.displacementA(t), 1e-17) << t;
    // Compression over the first half-period, tension over the second.
    const double f = e.contactForce(t);
    const bool firstHalf = std::fmod(t, period) < period / 2;
    EXPECT_EQ(f > 0, firstHalf) << t;
    EXPECT_DOUBLE_EQ(std::abs(f), e.contactForceMagnitude());
  }
  EXPECT_LT(e.velocityA(1e-5), 0.0);  // starts downward at v0/2
  EXPECT_DOUBLE_EQ(e.velocityA(1e-5), -0.5);
}

void expectRefused(BarImpactParameters p, const std::string& name) {
  try {
    BarImpactExact e(p);
    ADD_FAILURE() << name << " accepted";
  } catch (const choc::InputError& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("exact solution"), std::string::npos) << m;
    EXPECT_NE(m.find(name), std::string::npos) << m;
  }
}

TEST(BarImpactExact, InvalidParametersAreInputErrors) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto p = bars(5000.0, 0.0, false);
  auto q = p; q.length = 0.0; expectRefused(q, "length");
  q = p; q.length = nan; expectRefused(q, "length");
  q = p; q.waveSpeed = -5000.0; expectRefused(q, "waveSpeed");
  q = p; q.waveSpeed = inf; expectRefused(q, "waveSpeed");
  q = p; q.impedance = 0.0; expectRefused(q, "impedance");
  q = p; q.impactVelocity = 0.0; expectRefused(q, "impactVelocity");
  q = p; q.impactVelocity = nan; expectRefused(q, "impactVelocity");
  q = p; q.contactStart = -1e-5; expectRefused(q, "contactStart");
  q = p; q.contactStart = nan; expectRefused(q, "contactStart");
  EXPECT_THROW(BarImpactExact::barWaveSpeed(2e11, 0.0), choc::InputError);
  EXPECT_THROW(BarImpactExact::oedometricWaveSpeed(2e11, 0.5, 7800), choc::InputError);
  const BarImpactExact e(p);
  EXPECT_THROW(e.displacementA(nan), std::invalid_argument);
  EXPECT_THROW(e.velocityA(-1e-6), std::invalid_argument);
  EXPECT_THROW(e.contactForce(inf), std::invalid_argument);
}

}  // namespace

// A bar of length L dropped on a rigid wall (SDNV100: L = 0.2 m, c = 5000 m/s, v0 = -100 m/s,
// t0 = 2e-5 s): the contact end rests for 2L/c, the free end turns at t0 + L/c, both leave at
// -v0; the force Z|v0| over 2L/c reverses the bar's momentum; displacement and velocity agree.
TEST(BarImpactExact, RigidWallBothEnds) {
  BarImpactParameters p;
  p.length = 0.2;
  p.waveSpeed = 5000.0;
  p.impedance = 8000.0 * 5000.0 * 4e-4;
  p.impactVelocity = -100.0;
  p.contactStart = 2e-5;
  p.rigidWall = true;
  const BarImpactExact contact(p);
  p.freeEnd = true;
  const BarImpactExact free(p);
  EXPECT_DOUBLE_EQ(contact.contactDuration(), 8e-5);
  EXPECT_DOUBLE_EQ(contact.contactForceMagnitude(), 1.6e6);
  // The deck's rows (docs/verification/sdnv100.md).
  EXPECT_NEAR(contact.displacementA(2e-5), -2e-3, 1e-15);
  EXPECT_NEAR(contact.displacementA(1e-4), -2e-3, 1e-15);
  EXPECT_NEAR(free.displacementA(4e-5), -4e-3, 1e-15);
  EXPECT_NEAR(free.displacementA(1.2e-4), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(contact.velocityA(5e-5), 0.0);
  EXPECT_DOUBLE_EQ(contact.velocityA(1.2e-4), 100.0);
  EXPECT_DOUBLE_EQ(free.velocityA(4e-5), -100.0);
  EXPECT_DOUBLE_EQ(free.velocityA(1.2e-4), 100.0);
  EXPECT_DOUBLE_EQ(free.peakDisplacement(), 6e-3);
  const double m = 8000.0 * 4e-4 * 0.2;
  EXPECT_NEAR(contact.contactForceMagnitude() * contact.contactDuration(), 2 * m * 100.0, 1e-9);
  const double h = 1e-9;
  for (const BarImpactExact* e : {&contact, &free})
    for (double t = 1.3e-6; t < 2e-4; t += 1.7e-6) {
      if (std::abs(t - 2e-5) < 2 * h || std::abs(t - 6e-5) < 2 * h || std::abs(t - 1e-4) < 2 * h)
        continue;
      EXPECT_NEAR((e->displacementA(t + h) - e->displacementA(t - h)) / (2 * h), e->velocityA(t),
                  1e-4) << t;
    }
  p.bilateral = true;
  EXPECT_THROW(BarImpactExact{p}, choc::InputError);
}
