// Linear kinematic hardening (Prager-Ziegler) in small-strain J2 plasticity: the consistent
// tangent against central differences from a state with a back stress, the uniaxial
// tension-compression cycle against its closed form (the Bauschinger effect: reverse yield at
// the back stress minus the flow stress), the stored energy of the back stress and the
// dissipated work of each increment (never negative, though sigma : d eps_p is negative during
// reverse flow), and the refusals (negative, and in finite strain).
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "j2_point_helpers.hpp"
#include "materials/J2Plasticity.hpp"

namespace choc {
namespace {

using test::tangentAt;
using test::uniaxial;
using test::Uniaxial;

constexpr double kE = 206.9e9, kNu = 0.3, kYield = 250e6;

J2Plasticity material(double H, double Hk) {
  J2Parameters p = linearHardening(kE, kNu, kYield, H);
  p.kinematicHardening = Hk;
  return J2Plasticity(p, false);
}

TEST(KinematicHardening, TangentMatchesCentralDifferencesWithABackStress) {
  for (double H : {0.0, 2e9}) {
    const J2Plasticity m = material(H, 10e9);
    const Mat3 F1 = {{{1.006, 0.002, -0.001}, {0.003, 0.997, 0.001}, {-0.0005, 0.0025, 1.0005}}};
    EXPECT_TRUE(tangentAt(m, F1, m.initialState().data(), true)) << "H " << H;
    J2Response r;
    m.respond(F1, m.initialState().data(), false, r);
    ASSERT_TRUE(r.yielded);
    EXPECT_GT(std::abs(r.state[kJ2BackStress]), 0.0);  // the back stress moved
    Mat3 F2 = F1;  // turn the strain path: the relative stress's direction differs from the stress's
    F2[0][1] -= 0.006, F2[0][0] -= 0.002;
    EXPECT_TRUE(tangentAt(m, F2, r.state.data(), true)) << "H " << H;
    const Mat3 F3 = {{{1.0055, 0.002, -0.001}, {0.003, 0.997, 0.001}, {-0.0005, 0.0025, 1.0005}}};
    EXPECT_TRUE(tangentAt(m, F3, r.state.data(), false)) << "elastic unloading, H " << H;
  }
}

// Uniaxial stress with linear isotropic H and kinematic H_k: past yield the slope is
// E (H + H_k) / (E + H + H_k); the uniaxial back stress is X = H_k alpha, so unloading stays elastic
// down to X - (sigma_y + H alpha), where reverse flow starts and again hardens with H + H_k.
// Pure kinematic hardening (H = 0): the elastic range stays 2 sigma_y wide (the Bauschinger effect);
// pure isotropic (H_k = 0): reverse yield at -(sigma_y + H alpha), the old closed form.
TEST(KinematicHardening, UniaxialCycleMatchesTheClosedForm) {
  for (const auto& [H, Hk] : {std::pair{0.0, 10e9}, std::pair{2e9, 10e9}, std::pair{2e9, 0.0}}) {
    const J2Plasticity m = material(H, Hk);
    const double tol = 1e-9 * kYield, Ht = H + Hk;
    std::array<double, kJ2StateSize> s = m.initialState(), s1{};
    const double e1 = 0.01;
    for (int k = 1; k <= 10; ++k) {  // loading in ten increments (a proportional path)
      uniaxial(m, 1 + e1 * k / 10, s.data(), &s1);
      s = s1;
    }
    const double sigma1 = (kYield + Ht * e1) / (1 + Ht / kE), alpha = e1 - sigma1 / kE;
    const Uniaxial u1 = uniaxial(m, 1 + e1, s.data(), nullptr);
    EXPECT_NEAR(u1.axial, sigma1, tol) << "H " << H << " Hk " << Hk;
    EXPECT_NEAR(s[kJ2Alpha], alpha, 1e-9 * alpha);
    const double reverse = Hk * alpha - (kYield + H * alpha);  // the stress at reverse yield
    const double eYield = e1 - (sigma1 - reverse) / kE;
    EXPECT_NEAR(uniaxial(m, 1 + eYield + 1e-6, s.data(), nullptr).axial, reverse + kE * 1e-6, tol)
        << "still elastic just before reverse yield";
    const double e2 = eYield - 0.004;
    EXPECT_NEAR(uniaxial(m, 1 + e2, s.data(), nullptr).axial, reverse - Ht * (eYield - e2) / (1 + Ht / kE), tol)
        << "past reverse yield, H " << H << " Hk " << Hk;
  }
}

// After uniaxial flow to alpha the stored energy is the elastic sigma^2 / 2E plus the back
// stress's 1/2 H_k alpha^2; each increment of a tension-compression cycle dissipates xi : d eps_p >= 0
// (the trapezoid of the relative stress), while sigma : d eps_p turns negative in reverse flow with
// a large back stress (the energy stored in it comes back): the balance counts the former.
TEST(KinematicHardening, StoredAndDissipatedEnergy) {
  const double Hk = 20e9;
  const J2Plasticity m = material(0.0, Hk);
  std::array<double, kJ2StateSize> s = m.initialState(), s1{};
  const double e1 = 0.03;  // the back stress H_k alpha = 525 MPa exceeds sigma_y: reverse flow starts in tension
  for (int k = 1; k <= 12; ++k) {
    uniaxial(m, 1 + e1 * k / 12, s.data(), &s1);
    s = s1;
  }
  const double sigma1 = (kYield + Hk * e1) / (1 + Hk / kE), alpha = e1 - sigma1 / kE;
  EXPECT_NEAR(s[kJ2Energy], sigma1 * sigma1 / (2 * kE) + 0.5 * Hk * alpha * alpha, 1e-9 * s[kJ2Energy]);
  bool sigmaWorkNegative = false;
  double dissipated = 0.0;
  for (int k = 1; k <= 30; ++k) {  // down to -e1 and back: reverse flow while sigma > 0 at first
    const double e = e1 * (k <= 20 ? 1 - 0.1 * k : -1 + 0.2 * (k - 20));
    uniaxial(m, 1 + e, s.data(), &s1);
    double work = -(s1[kJ2Energy] - s[kJ2Energy]);  // the increment's work as the material records it
    for (int c = 0; c < 9; ++c)
      work += 0.5 * (s[size_t(kJ2Stress + c)] + s1[size_t(kJ2Stress + c)]) *
              (s1[size_t(kJ2Deformation + c)] - s[size_t(kJ2Deformation + c)]);
    EXPECT_GE(work, -1e-9 * kYield * e1) << "increment " << k;
    dissipated += work;
    const double dEpsP = s1[0] - s[0];  // the axial plastic strain's increment
    if (0.5 * (s[kJ2Stress] + s1[kJ2Stress]) * dEpsP < -1e-3 * kYield * std::abs(dEpsP)) sigmaWorkNegative = true;
    s = s1;
  }
  EXPECT_TRUE(sigmaWorkNegative) << "the cycle should show sigma : d eps_p < 0 (the back stress unloading)";
  EXPECT_GT(dissipated, 0.0);
}

TEST(KinematicHardening, RefusedWhenNegativeOrInFiniteStrain) {
  J2Parameters p = linearHardening(kE, kNu, kYield, 0.0);
  p.kinematicHardening = -1.0;
  EXPECT_THROW(J2Plasticity(p, false), std::invalid_argument);
  p.kinematicHardening = 1e9;
  EXPECT_THROW(J2Plasticity(p, true), std::invalid_argument);
  EXPECT_NO_THROW(J2Plasticity(p, false));
}

}  // namespace
}  // namespace choc
