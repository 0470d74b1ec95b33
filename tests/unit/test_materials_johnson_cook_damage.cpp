// Johnson and Cook's cumulative damage (JohnsonCookDamage.hpp) alone and in the return map: the
// failure strain written out independently, its refused parameters; the damage on proportional
// paths of known triaxiality (uniaxial tension 1/3, compression -1/3, shear 0: D = alpha / eps_f
// exactly, in both kinematics where the path is proportional); the sum over increments with the
// rate and the heating; nothing while elastic or unloading; and the stress, the tangent and every
// other state entry unchanged by it (reported, not coupled).
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "j2_point_helpers.hpp"
#include "materials/J2Plasticity.hpp"
#include "materials/JohnsonCookDamage.hpp"

namespace choc {
namespace {

using test::uniaxial;

constexpr double kE = 206.9e9, kNu = 0.3, kRho = 7830;

JohnsonCookParameters steel(double taylorQuinney) {
  JohnsonCookParameters p;
  p.A = 806e6, p.B = 614e6, p.n = 0.168, p.C = 0.0089, p.referenceRate = 1.0, p.m = 1.1;
  p.referenceTemperature = 20, p.meltingTemperature = 1540, p.initialTemperature = 20;
  p.specificHeat = 460, p.taylorQuinney = taylorQuinney, p.density = kRho;
  return p;
}

// 4340 steel's fit (Johnson and Cook 1985, table 2).
JohnsonCookDamageParameters damage4340() {
  JohnsonCookDamageParameters d;
  d.enabled = true, d.D1 = 0.05, d.D2 = 3.44, d.D3 = -2.12, d.D4 = 0.002, d.D5 = 0.61;
  return d;
}

J2Parameters withDamage(double taylorQuinney, bool damage = true) {
  J2Parameters p = linearHardening(kE, kNu, 0.0, 0.0);
  p.johnsonCook = true;
  p.jc = steel(taylorQuinney);
  if (damage) p.damage = damage4340();
  return p;
}

double quasiStaticFailure(double triaxiality) { return 0.05 + 3.44 * std::exp(-2.12 * triaxiality); }

TEST(JohnsonCookDamage, FailureStrainFormula) {
  const JohnsonCookDamage d(damage4340(), steel(0.9));
  const double expected = (0.05 + 3.44 * std::exp(-2.12 * 0.5)) * (1 + 0.002 * std::log(2e4)) * (1 + 0.61 * 380.0 / 1520);
  EXPECT_NEAR(d.failureStrain(0.5, 2e-4, 1e-8, 400), expected, 1e-14 * expected);  // a rate of 2e4 / s
  // Below the reference rate, with no duration and below T_0: the quasi-static, cold failure strain.
  EXPECT_DOUBLE_EQ(d.failureStrain(-0.3, 1e-9, 1e-8, 20), quasiStaticFailure(-0.3));
  EXPECT_DOUBLE_EQ(d.failureStrain(-0.3, 1e-3, 0.0, -50), quasiStaticFailure(-0.3));
  // T* is clamped at 1 above the melting temperature.
  EXPECT_DOUBLE_EQ(d.failureStrain(0.0, 0.0, 0.0, 3000), (0.05 + 3.44) * 1.61);
}

TEST(JohnsonCookDamage, RefusesParametersOutOfRange) {
  auto refused = [](auto change) {
    JohnsonCookDamageParameters d = damage4340();
    change(d);
    EXPECT_THROW(JohnsonCookDamage(d, steel(0.9)), std::invalid_argument);
  };
  refused([](JohnsonCookDamageParameters& d) { d.D1 = -0.09; });  // Ti-6Al-4V's fit
  refused([](JohnsonCookDamageParameters& d) { d.D2 = -1; });
  refused([](JohnsonCookDamageParameters& d) { d.D1 = 0, d.D2 = 0; });
  refused([](JohnsonCookDamageParameters& d) { d.D3 = std::nan(""); });
  refused([](JohnsonCookDamageParameters& d) { d.D4 = -0.01; });
  refused([](JohnsonCookDamageParameters& d) { d.D5 = -0.5; });
  JohnsonCookDamageParameters off;
  off.D1 = -1;  // not enabled: not checked
  EXPECT_NO_THROW(JohnsonCookDamage(off, steel(0.9)));
  // Damage needs Johnson-Cook's flow stress (its reference rate and temperatures).
  J2Parameters linear = linearHardening(kE, kNu, 400e6, 100e6);
  linear.damage = damage4340();
  EXPECT_THROW(J2Plasticity(linear, false), std::invalid_argument);
}

// Uniaxial stress loaded in increments, quasi-static (dt = 0) and isothermal: the triaxiality is
// 1/3 in tension and -1/3 in compression at every increment (the lateral stress is zero to
// round-off), so D = alpha / eps_f(+-1/3).
TEST(JohnsonCookDamageClosedForm, UniaxialTensionAndCompression) {
  for (bool finite : {false, true}) {
    const J2Plasticity m(withDamage(0.0), finite);
    for (double sign : {1.0, -1.0}) {
      auto s = m.initialState();
      std::array<double, kJ2StateSize> next{};
      for (int k = 1; k <= 8; ++k) {
        const double e = sign * 0.02 * k;
        const test::Uniaxial u = uniaxial(m, finite ? std::exp(e) : 1 + e, s.data(), &next);
        s = next;
        ASSERT_GT(u.alpha, 0.0);
        const double expected = u.alpha / quasiStaticFailure(sign / 3);
        EXPECT_NEAR(s[kJ2Damage], expected, 1e-9 * expected) << "finite " << finite << " sign " << sign << " k " << k;
      }
    }
  }
}

// Small-strain simple shear (F = I + gamma e_x e_y): the stress is deviatoric, the triaxiality 0,
// D = alpha / (D1 + D2).
TEST(JohnsonCookDamageClosedForm, SimpleShearHasTheFailureStrainOfZeroTriaxiality) {
  const J2Plasticity m(withDamage(0.0), false);
  auto s = m.initialState();
  for (int k = 1; k <= 5; ++k) {
    J2Response r;
    m.respond({{{1, 0.02 * k, 0}, {0, 1, 0}, {0, 0, 1}}}, s.data(), false, r);
    s = r.state;
    ASSERT_TRUE(r.yielded);
    const double expected = s[kJ2Alpha] / 3.49;
    EXPECT_NEAR(s[kJ2Damage], expected, 1e-9 * expected) << k;
  }
}

// With the rate (dt = 10 ns per increment of 1 % strain: 1e6 / s) and the heating: the sum of each
// increment's d alpha over eps_f at its rate and at the temperature it started from.
TEST(JohnsonCookDamageClosedForm, SumsTheIncrementsWithRateAndHeating) {
  const J2Plasticity m(withDamage(0.9), false);
  const double dt = 1e-8;
  auto s = m.initialState();
  std::array<double, kJ2StateSize> next{};
  double expected = 0.0;
  for (int k = 1; k <= 10; ++k) {
    uniaxial(m, 1 + 0.01 * k, s.data(), &next, dt);
    const double dalpha = next[kJ2Alpha] - s[kJ2Alpha], T = s[kJ2Temperature];
    if (dalpha > 0)
      expected += dalpha / (quasiStaticFailure(1.0 / 3) * (1 + 0.002 * std::log(std::max(dalpha / dt, 1.0))) *
                            (1 + 0.61 * (T - 20) / 1520));
    s = next;
  }
  EXPECT_GT(s[kJ2Temperature], 20.0 + 1.0);  // heated: the temperature term acts
  EXPECT_NEAR(s[kJ2Damage], expected, 1e-9 * expected);
}

// Below yield and while unloading elastically the damage stays where it was.
TEST(JohnsonCookDamage, GrowsOnlyWhileThePointYields) {
  const J2Plasticity m(withDamage(0.0), true);
  std::array<double, kJ2StateSize> next{};
  const auto virgin = m.initialState();
  uniaxial(m, 1.002, virgin.data(), &next);  // sigma = 4e8 Pa < A
  EXPECT_EQ(next[kJ2Damage], 0.0);
  auto s = virgin;
  uniaxial(m, 1.05, s.data(), &next);
  s = next;
  ASSERT_GT(s[kJ2Damage], 0.0);
  uniaxial(m, 1.048, s.data(), &next);  // unloading
  EXPECT_EQ(next[kJ2Alpha], s[kJ2Alpha]);
  EXPECT_EQ(next[kJ2Damage], s[kJ2Damage]);
}

// Reported, not coupled: with and without damage the stress, the tangent and every state entry
// but D agree bit for bit, at a general yielding F with rate and heating, in both kinematics.
TEST(JohnsonCookDamage, LeavesTheResponseUnchanged) {
  const Mat3 F = {{{1.012, 0.004, -0.003}, {0.006, 0.993, 0.002}, {-0.001, 0.005, 1.001}}};
  for (bool finite : {false, true}) {
    const J2Plasticity with(withDamage(0.9), finite), without(withDamage(0.9, false), finite);
    J2Response a, b;
    with.respond(F, with.initialState().data(), true, a, false, 1e-8);
    without.respond(F, without.initialState().data(), true, b, false, 1e-8);
    ASSERT_TRUE(a.yielded && b.yielded);
    EXPECT_GT(a.state[kJ2Damage], 0.0);
    EXPECT_EQ(b.state[kJ2Damage], 0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_EQ(a.P[i][j], b.P[i][j]);
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) EXPECT_EQ(a.A[i][j], b.A[i][j]);
    for (int k = 0; k < kJ2Damage; ++k) EXPECT_EQ(a.state[size_t(k)], b.state[size_t(k)]) << k;
  }
}

}  // namespace
}  // namespace choc
