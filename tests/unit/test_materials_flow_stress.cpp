// The flow-stress laws of J2 plasticity (FlowStress.hpp) alone and in the return map: a flow
// curve's interpolation, Johnson-Cook's value and slope (hardening, rate, temperature), their
// refused parameters; the consistent tangent against central differences with each law; the
// uniaxial closed forms (a flow curve's stress-strain curve, Johnson-Cook at a fixed rate and
// with thermal softening); the adiabatic heating against the plastic work.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "j2_point_helpers.hpp"
#include "materials/FlowStress.hpp"
#include "materials/J2Plasticity.hpp"

namespace choc {
namespace {

using test::tangentAt;
using test::uniaxial;

constexpr double kE = 206.9e9, kNu = 0.3, kRho = 7830;  // BENCHMARKS.md section 11's 42CrMo4

JohnsonCookParameters steel() {
  JohnsonCookParameters p;
  p.A = 806e6, p.B = 614e6, p.n = 0.168, p.C = 0.0089, p.referenceRate = 1.0, p.m = 1.1;
  p.referenceTemperature = 20, p.meltingTemperature = 1540, p.initialTemperature = 20;
  p.specificHeat = 460, p.taylorQuinney = 0.9, p.density = kRho;
  return p;
}

J2Parameters johnsonCook(const JohnsonCookParameters& jc) {
  J2Parameters p = linearHardening(kE, kNu, 0.0, 0.0);
  p.johnsonCook = true;
  p.jc = jc;
  return p;
}

// sigma_y = 400 MPa, rising by 200 MPa over alpha = 0.01, by 50 MPa more to 0.1, then constant.
FlowCurve curve() { return {{0.0, 0.01, 0.1}, {400e6, 600e6, 650e6}}; }

J2Parameters withCurve() {
  J2Parameters p = linearHardening(kE, kNu, 0.0, 0.0);
  p.curve = curve();
  return p;
}

TEST(FlowStress, CurveInterpolatesAndStaysConstantBeyondItsEnd) {
  const FlowStress f = FlowStress::curve(curve());
  EXPECT_DOUBLE_EQ(f.at(0.0, 0.0, 0.0, 0.0).stress, 400e6);
  EXPECT_DOUBLE_EQ(f.at(0.0, 0.0, 0.0, 0.0).slope, 2e10);
  EXPECT_DOUBLE_EQ(f.at(0.004, 0.001, 0.0, 0.0).stress, 500e6);  // alpha_old + dalpha = 0.005
  EXPECT_DOUBLE_EQ(f.at(0.055, 0.0, 0.0, 0.0).stress, 625e6);
  EXPECT_NEAR(f.at(0.055, 0.0, 0.0, 0.0).slope, 50e6 / 0.09, 1e-6);
  EXPECT_DOUBLE_EQ(f.at(0.3, 0.0, 0.0, 0.0).stress, 650e6);
  EXPECT_DOUBLE_EQ(f.at(0.3, 0.0, 0.0, 0.0).slope, 0.0);
}

TEST(FlowStress, RefusesCurvesThatAreNotFlowCurves) {
  EXPECT_THROW(FlowStress::curve({{0.001, 0.01}, {400e6, 500e6}}), std::invalid_argument);  // not from 0
  EXPECT_THROW(FlowStress::curve({{0.0, 0.01, 0.01}, {400e6, 500e6, 600e6}}), std::invalid_argument);
  EXPECT_THROW(FlowStress::curve({{0.0, 0.01}, {400e6, 399e6}}), std::invalid_argument);  // softening
  EXPECT_THROW(FlowStress::curve({{0.0, 0.01}, {0.0, 100e6}}), std::invalid_argument);
  EXPECT_THROW(FlowStress::curve({{0.0}, {}}), std::invalid_argument);
  EXPECT_NO_THROW(FlowStress::curve({{0.0}, {400e6}}));  // perfectly plastic
}

// The formula written out independently of FlowStress, and its slope by central differences.
TEST(FlowStress, JohnsonCookValueAndSlope) {
  const JohnsonCookParameters p = steel();
  const FlowStress f = FlowStress::johnsonCook(p);
  const double alphaOld = 0.3, dalpha = 2e-4, dt = 1e-8, T = 400;  // a rate of 2e4 / s
  const double expected = (806e6 + 614e6 * std::pow(0.3002, 0.168)) * (1 + 0.0089 * std::log(2e4)) *
                          (1 - std::pow((400.0 - 20) / 1520, 1.1));
  const FlowStress::Value v = f.at(alphaOld, dalpha, dt, T);
  EXPECT_NEAR(v.stress, expected, 1e-12 * expected);
  const double h = 1e-7;
  const double fd = (f.at(alphaOld, dalpha + h, dt, T).stress - f.at(alphaOld, dalpha - h, dt, T).stress) / (2 * h);
  EXPECT_NEAR(v.slope, fd, 1e-6 * std::abs(fd));
  // Below the reference rate the quasi-static law; at or above the melting point no strength.
  EXPECT_NEAR(f.at(0.3, 1e-9, 1e-8, 20).stress, 806e6 + 614e6 * std::pow(0.3 + 1e-9, 0.168), 1e-3);
  EXPECT_EQ(f.at(0.3, 0.0, 1e-8, 1540).stress, 0.0);
  EXPECT_EQ(f.at(0.3, 0.0, 1e-8, 2000).stress, 0.0);
  EXPECT_NEAR(f.heatPerWork(), 0.9 / (kRho * 460), 1e-18);
}

TEST(FlowStress, RefusesJohnsonCookParametersOutOfRange) {
  auto refused = [](auto change) {
    JohnsonCookParameters p = steel();
    change(p);
    EXPECT_THROW(FlowStress::johnsonCook(p), std::invalid_argument);
  };
  refused([](JohnsonCookParameters& p) { p.A = 0; });
  refused([](JohnsonCookParameters& p) { p.B = -1; });
  refused([](JohnsonCookParameters& p) { p.n = 0; });
  refused([](JohnsonCookParameters& p) { p.n = 1.5; });
  refused([](JohnsonCookParameters& p) { p.C = -0.01; });
  refused([](JohnsonCookParameters& p) { p.referenceRate = 0; });
  refused([](JohnsonCookParameters& p) { p.m = 0; });
  refused([](JohnsonCookParameters& p) { p.meltingTemperature = 20; });
  refused([](JohnsonCookParameters& p) { p.initialTemperature = 1540; });
  refused([](JohnsonCookParameters& p) { p.taylorQuinney = 1.1; });
  refused([](JohnsonCookParameters& p) { p.specificHeat = 0; });
  JohnsonCookParameters isothermal = steel();
  isothermal.taylorQuinney = 0, isothermal.specificHeat = 0;
  EXPECT_NO_THROW(FlowStress::johnsonCook(isothermal));
  EXPECT_THROW(J2Plasticity(johnsonCook(JohnsonCookParameters{}), true), std::invalid_argument);
}

const Mat3 kGeneral = {{{1.012, 0.004, -0.003}, {0.006, 0.993, 0.002}, {-0.001, 0.005, 1.001}}};

// The consistent tangent with the rate term (dt = 10 ns: rates of 1e5 / s) and at a heated point.
TEST(FlowStress, TangentMatchesCentralDifferencesWithEachLaw) {
  for (bool finite : {false, true}) {
    const J2Plasticity jc(johnsonCook(steel()), finite), table(withCurve(), finite);
    for (const J2Plasticity* m : {&jc, &table}) {
      auto s = m->initialState();
      EXPECT_TRUE(tangentAt(*m, kGeneral, s.data(), true, 1e-8)) << "finite " << finite;
      J2Response r;
      m->respond(kGeneral, s.data(), false, r, false, 1e-8);
      s = r.state;  // yielded, and heated with Johnson-Cook
      Mat3 F = kGeneral;
      F[0][1] += 0.004, F[2][2] -= 0.003;
      EXPECT_TRUE(tangentAt(*m, F, s.data(), true, 1e-8)) << "finite " << finite;
      EXPECT_TRUE(tangentAt(*m, F, s.data(), true, 0.0)) << "finite " << finite;  // quasi-static
    }
  }
}

// Uniaxial stress along a flow curve in one increment (a proportional path: backward Euler is
// exact): at a plastic strain alpha, sigma = sigma_y(alpha) at the total strain alpha + sigma / E
// (finite strain: tau and the logarithmic strain).
TEST(FlowStressClosedForm, UniaxialStressFollowsTheFlowCurve) {
  const FlowStress f = FlowStress::curve(curve());
  for (bool finite : {false, true}) {
    const J2Plasticity m(withCurve(), finite);
    for (double alpha : {0.002, 0.01, 0.04, 0.2}) {
      const double sigma = f.at(alpha, 0.0, 0.0, 0.0).stress, e = alpha + sigma / kE;
      const test::Uniaxial u = uniaxial(m, finite ? std::exp(e) : 1 + e, m.initialState().data(), nullptr);
      EXPECT_NEAR(u.axial, sigma, 1e-9 * sigma) << "alpha " << alpha << " finite " << finite;
      EXPECT_NEAR(u.alpha, alpha, 1e-9) << "alpha " << alpha << " finite " << finite;
    }
  }
}

// Johnson-Cook in uniaxial stress, small strain, loaded in increments of dt at a strain rate of
// 1e4 / s: after each increment the stress is the law at the increment's plastic rate
// dalpha / dt and the point's temperature before it; the temperature rises by chi / (rho c) times
// sum sigma_y dalpha (the documented heating, sigma_y the increment's flow stress), to the
// uniaxial bisection's tolerance; and the trapezoidal work the energy balance counts is that sum
// within the difference of the two quadratures, sum |d sigma| dalpha / 2.
TEST(FlowStressClosedForm, JohnsonCookAtAStrainRateWithHeating) {
  const JohnsonCookParameters p = steel();
  const J2Plasticity m(johnsonCook(p), false);
  const double rate = 1e4, de = 2e-4, dt = de / rate;
  auto s = m.initialState();
  double work = 0.0, flowWork = 0.0, quadratureGap = 0.0, lastStress = 0.0;
  for (int k = 1; k <= 500; ++k) {  // to a strain of 0.1
    std::array<double, kJ2StateSize> next{};
    const test::Uniaxial u = uniaxial(m, 1 + k * de, s.data(), &next, dt);
    const double dalpha = next[kJ2Alpha] - s[kJ2Alpha];
    if (dalpha > 0) {
      const double T = s[kJ2Temperature];
      const double expected = (p.A + p.B * std::pow(next[kJ2Alpha], p.n)) *
                              (1 + p.C * std::log(std::max(dalpha / dt, 1.0))) *
                              (1 - std::pow((T - p.referenceTemperature) / (p.meltingTemperature - p.referenceTemperature), p.m));
      ASSERT_NEAR(u.axial, expected, 1e-9 * expected) << "increment " << k;
      quadratureGap += 0.5 * std::abs(u.axial - lastStress) * dalpha;
      flowWork += u.axial * dalpha;
    }
    lastStress = u.axial;
    work += 0.5 * (s[kJ2Stress] + u.axial) * de - (next[kJ2Energy] - s[kJ2Energy]);
    s = next;
  }
  EXPECT_GT(s[kJ2Alpha], 0.09);
  const double rise = s[kJ2Temperature] - p.initialTemperature;
  EXPECT_GT(rise, 10.0);  // about 0.1 x 1.2 GPa x 0.9 / (7830 x 460)
  EXPECT_NEAR(rise, m.flowStress().heatPerWork() * flowWork, 1e-8 * rise);
  EXPECT_NEAR(work, flowWork, quadratureGap + 1e-9 * work);
}

// The heating is chi sigma_y d alpha / (rho c) (issue 71: it followed the increment's measured
// dissipation, which an unloading or elastic increment's quadrature error makes negative: the
// temperature fell below T_0 and decreased between states). On a path that yields in tension,
// unloads, reverses into compression and turns into shear, in both kinematics and with the rate
// term: the temperature never falls below T_0, never decreases, is unchanged by every increment
// with d alpha = 0, and rises by exactly chi sigma_y d alpha / (rho c) by every other.
TEST(FlowStress, JohnsonCookHeatingFollowsTheFlowStress) {
  const JohnsonCookParameters p = steel();
  for (bool finite : {false, true}) {
    const J2Plasticity m(johnsonCook(p), finite);
    auto s = m.initialState();
    const double dt = 1e-8;
    int elastic = 0, plastic = 0;
    for (int k = 1; k <= 400; ++k) {
      const double t = k / 100.0;  // 0-1 tension to 1 %, 1-2 back, 2-3 compression, 3-4 shear
      const double e = t <= 1 ? 0.01 * t : t <= 2 ? 0.01 * (2 - t) : t <= 3 ? -0.01 * (t - 2) : -0.01;
      const double g = t <= 3 ? 0.0 : 0.02 * (t - 3);
      const Mat3 F = {{{1 + e, g, 0}, {0, 1 - 0.3 * e, 0}, {0, 0, 1 - 0.3 * e}}};
      J2Response r;
      m.respond(F, s.data(), false, r, false, dt);
      const double dalpha = r.state[kJ2Alpha] - s[kJ2Alpha], T = r.state[kJ2Temperature];
      ASSERT_GE(dalpha, 0.0) << "increment " << k;
      ASSERT_GE(T, p.initialTemperature) << "increment " << k << " finite " << finite;
      ASSERT_GE(T, s[kJ2Temperature]) << "increment " << k << " finite " << finite;
      if (dalpha == 0.0) {
        ASSERT_EQ(T, s[kJ2Temperature]) << "elastic increment " << k << " finite " << finite;
        ++elastic;
      } else {
        const double sigmaY = m.flowStress().at(s[kJ2Alpha], dalpha, dt, s[kJ2Temperature]).stress;
        // the rise as a difference of two temperatures of about T carries their round-off, 2 eps T;
        // sigma_y recomputed from d alpha (itself a difference) agrees to far below 1e-10
        const double roundoff = 4 * std::numeric_limits<double>::epsilon() * T;
        ASSERT_NEAR(T - s[kJ2Temperature], m.flowStress().heatPerWork() * sigmaY * dalpha,
                    1e-10 * (T - s[kJ2Temperature]) + roundoff)
            << "increment " << k << " finite " << finite;
        ++plastic;
      }
      s = r.state;
    }
    EXPECT_GT(elastic, 50) << "finite " << finite;  // the unloading and the reversal's start
    EXPECT_GT(plastic, 100) << "finite " << finite;
  }
}

// Johnson-Cook's return in finite strain is objective like J2's: a rotation R applied after F, from
// a heated, yielded state and with the rate term (dt = 10 ns), turns the stress, P(R F) = R P(F),
// and leaves alpha and the stored energy as they are. (The temperature is not compared: its source,
// the trapezoid of P : dF over the increment, counts a rotation within one increment; 0.9 rad
// here moves it by 45 K, a rotation of 1e-4 rad per step by far less. A scene drawn turned as a
// whole turns F_n too and is exact: cli.taylor_bar_3d.)
TEST(FlowStress, JohnsonCookIsObjective) {
  const J2Plasticity m(johnsonCook(steel()), true);
  J2Response first;
  m.respond(kGeneral, m.initialState().data(), false, first, false, 1e-8);
  ASSERT_TRUE(first.yielded);
  const Mat3 F = {{{1.03, 0.012, -0.004}, {0.007, 0.985, 0.009}, {-0.006, 0.003, 0.99}}};
  const double c = std::cos(0.9), s = std::sin(0.9);
  const Mat3 R = multiply(Mat3{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}}, Mat3{{{1, 0, 0}, {0, c, s}, {0, -s, c}}});
  J2Response a, b;
  m.respond(F, first.state.data(), false, a, false, 1e-8);
  m.respond(multiply(R, F), first.state.data(), false, b, false, 1e-8);
  ASSERT_TRUE(a.yielded);
  const Mat3 RP = multiply(R, a.P);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(b.P[i][j], RP[i][j], 1e-12 * 806e6 * 10);  // round-off of the eigen solve
  EXPECT_NEAR(b.state[kJ2Alpha], a.state[kJ2Alpha], 1e-13);
  EXPECT_NEAR(b.energy, a.energy, 1e-12 * a.energy);
}

// A point heated to the melting temperature has no deviatoric strength.
TEST(FlowStressClosedForm, MeltedPointCarriesNoShear) {
  const J2Plasticity m(johnsonCook(steel()), true);
  auto s = m.initialState();
  s[kJ2Temperature] = 1540;
  J2Response r;
  m.respond({{{1, 0.01, 0}, {0.01, 1, 0}, {0, 0, 1}}}, s.data(), false, r, false, 1e-8);
  EXPECT_TRUE(r.yielded);
  EXPECT_NEAR(vonMises(r.cauchy), 0.0, 1e-6 * kE * 0.01);
}

}  // namespace
}  // namespace choc
