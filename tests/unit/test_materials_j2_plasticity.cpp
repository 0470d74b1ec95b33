// J2 plasticity at one point: the consistent tangent against central differences of the
// return map (elastic and plastic branches, a yielded history, equal principal stretches, just
// past the yield surface), the closed forms of uniaxial stress (loading, unloading, reverse
// yield) and simple shear, objectivity in finite strain, and the refused parameters.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "j2_point_helpers.hpp"
#include "materials/J2Plasticity.hpp"

namespace choc {
namespace {

using test::Dense;
using test::tangentAt;
using test::uniaxial;
using test::Uniaxial;

constexpr double kE = 117e9, kNu = 0.35, kYield = 400e6, kH = 100e6;  // the Taylor bar's copper

J2Plasticity material(bool finite, double H = kH) { return J2Plasticity(linearHardening(kE, kNu, kYield, H), finite); }

// A state after plastic flow: the response to F1 from a virgin point.
std::array<double, kJ2StateSize> flowedState(const J2Plasticity& m, const Mat3& F1) {
  J2Response r;
  const auto s0 = m.initialState();
  m.respond(F1, s0.data(), false, r);
  EXPECT_TRUE(r.yielded);
  return r.state;
}

const Mat3 kGeneral = {{{1.012, 0.004, -0.003}, {0.006, 0.993, 0.002}, {-0.001, 0.005, 1.001}}};
const Mat3 kLarge = {{{1.31, 0.22, -0.05}, {0.08, 0.87, 0.12}, {-0.11, 0.04, 0.95}}};

TEST(J2Plasticity, TangentInTheElasticBranch) {
  for (bool finite : {false, true}) {
    const J2Plasticity m = material(finite);
    const Mat3 F = {{{1.001, 0.0005, 0}, {0.0002, 0.9995, 0}, {0, 0.0001, 1.0002}}};
    EXPECT_TRUE(tangentAt(m, F, m.initialState().data(), false)) << "finite " << finite;
  }
}

TEST(J2Plasticity, TangentInThePlasticBranch) {
  for (bool finite : {false, true}) {
    const J2Plasticity m = material(finite);
    EXPECT_TRUE(tangentAt(m, kGeneral, m.initialState().data(), true)) << "finite " << finite;
    const auto s = flowedState(m, kGeneral);  // a yielded history, then a further, different strain
    Mat3 F = kGeneral;
    F[0][1] += 0.01, F[2][2] -= 0.008;
    EXPECT_TRUE(tangentAt(m, F, s.data(), true)) << "finite " << finite;
  }
  const J2Plasticity m = material(true);
  EXPECT_TRUE(tangentAt(m, kLarge, m.initialState().data(), true));
  EXPECT_TRUE(tangentAt(m, kLarge, flowedState(m, kGeneral).data(), true));
}

// Uniaxial: two principal stretches equal, the spin terms at their limit.
TEST(J2Plasticity, TangentWithEqualPrincipalStretches) {
  for (bool finite : {false, true}) {
    const J2Plasticity m = material(finite);
    const Mat3 F = {{{1.02, 0, 0}, {0, 0.993, 0}, {0, 0, 0.993}}};
    EXPECT_TRUE(tangentAt(m, F, m.initialState().data(), true)) << "finite " << finite;
    const Mat3 dilated = {{{1.001, 0, 0}, {0, 1.001, 0}, {0, 0, 1.001}}};  // three equal, elastic
    EXPECT_TRUE(tangentAt(m, dilated, m.initialState().data(), false)) << "finite " << finite;
  }
}

// Just past the yield surface (f / sigma_y = 1e-3): the plastic tangent, not the elastic one.
TEST(J2Plasticity, TangentJustPastYield) {
  for (bool finite : {false, true}) {
    const J2Plasticity m = material(finite);
    const double mu = m.shearModulus();
    // Pure shear F = I + g (e1 e2 + e2 e1): ||e|| = g sqrt(2) (small strain); yield at 2 mu ||e|| = sqrt(2/3) sy.
    const double gy = std::sqrt(2.0 / 3.0) * kYield / (2 * mu * std::sqrt(2.0));
    const double g = gy * (1 + 1e-3);
    const Mat3 F = {{{1, g, 0}, {g, 1, 0}, {0, 0, 1}}};
    J2Response r;
    m.respond(F, m.initialState().data(), false, r);
    ASSERT_TRUE(r.yielded) << "finite " << finite;
    EXPECT_TRUE(tangentAt(m, F, m.initialState().data(), true)) << "finite " << finite;
  }
}

TEST(J2PlasticityClosedForm, UniaxialLoadingUnloadingAndReverseYield) {
  for (bool finite : {false, true}) {
    const J2Plasticity m = material(finite);
    auto stretch = [&](double e) { return finite ? std::exp(e) : 1 + e; };
    const double tol = 1e-9 * kYield;  // the bisection's lateral residual, 2^-200 of its range, and round-off
    std::array<double, kJ2StateSize> s = m.initialState(), s1{};
    // Below yield.
    const double e0 = 0.5 * kYield / kE;
    EXPECT_NEAR(uniaxial(m, stretch(e0), s.data(), nullptr).axial, kE * e0, tol);
    // Past yield, in one increment from the virgin state and in ten (the same on a proportional path).
    const double e1 = finite ? 0.4 : 0.02;
    const double expected = (kYield + kH * e1) / (1 + kH / kE);
    EXPECT_NEAR(uniaxial(m, stretch(e1), s.data(), nullptr).axial, expected, tol) << "finite " << finite;
    for (int k = 1; k <= 10; ++k) {
      const Uniaxial u = uniaxial(m, stretch(e1 * k / 10), s.data(), &s1);
      s = s1;
      if (k == 10) {
        EXPECT_NEAR(u.axial, expected, tol) << "finite " << finite;
        EXPECT_NEAR(u.alpha, e1 - expected / kE, 1e-9 * e1);
      }
    }
    // Unloading is elastic, slope E, down to no stress at the permanent strain alpha.
    const double alpha = s[kJ2Alpha];
    const double back = e1 - 0.5 * expected / kE;
    EXPECT_NEAR(uniaxial(m, stretch(back), s.data(), nullptr).axial, 0.5 * expected, tol);
    EXPECT_NEAR(uniaxial(m, stretch(alpha), s.data(), nullptr).axial, 0.0, tol);
    // Reverse yield at -(sigma_y + H alpha) (isotropic hardening): just before and beyond it.
    const double reverse = kYield + kH * alpha;
    const double eYield = alpha - reverse / kE;
    EXPECT_NEAR(uniaxial(m, stretch(eYield + 1e-6), s.data(), nullptr).axial, -reverse + kE * 1e-6, tol);
    const double e2 = eYield - 0.01;
    const Uniaxial u2 = uniaxial(m, stretch(e2), s.data(), nullptr);
    // Past the reverse yield: |sigma| = sigma_y + H (alpha + dalpha), e2 = alpha - dalpha - |sigma| / E,
    // so |sigma| = reverse + H (eYield - e2) / (1 + H / E).
    const double sigma2 = reverse + kH * (eYield - e2) / (1 + kH / kE);
    EXPECT_NEAR(u2.axial, -sigma2, tol) << "finite " << finite;
  }
}

// Simple shear (small strain), eps_12 = gamma / 2: tau = mu gamma to tau_y = sigma_y / sqrt 3,
// then tau = (sqrt 3 sigma_y + H gamma) / (3 + H / mu).
TEST(J2PlasticityClosedForm, SimpleShear) {
  const J2Plasticity m = material(false);
  const double mu = m.shearModulus();
  for (double gamma : {0.5 * kYield / (std::sqrt(3.0) * mu), 0.01, 0.05}) {
    J2Response r;
    m.respond({{{1, gamma, 0}, {0, 1, 0}, {0, 0, 1}}}, m.initialState().data(), false, r);
    const double elastic = mu * gamma;
    const double expected = r.yielded ? (std::sqrt(3.0) * kYield + kH * gamma) / (3 + kH / mu) : elastic;
    EXPECT_EQ(r.yielded, elastic > kYield / std::sqrt(3.0));
    EXPECT_NEAR(r.P[0][1], expected, 1e-12 * kYield);
    EXPECT_NEAR(r.P[0][0], 0.0, 1e-12 * kYield);
    EXPECT_NEAR(vonMises(r.cauchy), r.yielded ? kYield + kH * r.state[kJ2Alpha] : std::sqrt(3.0) * elastic, 1e-9 * kYield);
  }
}

// Finite strain: a rotation R applied after F turns the stress, P(R F) = R P(F), and leaves the
// plastic state, alpha and the energy as they are.
TEST(J2Plasticity, FiniteStrainIsObjective) {
  const J2Plasticity m = material(true);
  const double c = std::cos(1.1), s = std::sin(1.1);
  const Mat3 R = multiply(Mat3{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}}, Mat3{{{1, 0, 0}, {0, c, s}, {0, -s, c}}});
  const auto state = flowedState(m, kGeneral);
  J2Response a, b;
  m.respond(kLarge, state.data(), false, a);
  m.respond(multiply(R, kLarge), state.data(), false, b);
  const Mat3 RP = multiply(R, a.P);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(b.P[i][j], RP[i][j], 1e-12 * kYield * 10);
  for (int k = 0; k <= kJ2Alpha; ++k) EXPECT_NEAR(b.state[size_t(k)], a.state[size_t(k)], 1e-13);
  EXPECT_NEAR(b.energy, a.energy, 1e-12 * a.energy);
}

TEST(J2Plasticity, RefusesParametersOutOfRange) {
  EXPECT_THROW(J2Plasticity(linearHardening(kE, kNu, -1.0, kH), true), std::invalid_argument);
  EXPECT_THROW(J2Plasticity(linearHardening(kE, kNu, 0.0, kH), true), std::invalid_argument);
  EXPECT_THROW(J2Plasticity(linearHardening(kE, kNu, kYield, -1.0), false), std::invalid_argument);
  EXPECT_THROW(J2Plasticity(linearHardening(kE, 0.5, kYield, kH), false), std::invalid_argument);
  J2Response r;
  EXPECT_THROW(material(true).respond({{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, material(true).initialState().data(), false, r),
               std::domain_error);
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// The dissipated work of a uniaxial path: to the yield strain in one increment, then n plastic
// increments to eps_end. Small strain: sigma is linear in eps_p on the plastic path, so the
// trapezoidal rule is exact: W_p = sigma_y alpha + H alpha^2 / 2. Finite strain: the same in
// tau and the logarithmic strains, which P : dF by the trapezoid approaches at O(1/n^2).
double uniaxialPlasticWork(const J2Plasticity& m, double epsEnd, int n, double& alpha) {
  auto stretch = [&](double e) { return m.finiteStrain() ? std::exp(e) : 1 + e; };
  std::array<double, kJ2StateSize> s = m.initialState(), next{};
  const double eY = kYield / kE;
  double work = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double e = eY + (epsEnd - eY) * k / n;
    // the lateral stretch of zero lateral stress, as in uniaxial() above
    double lo = 0.5, hi = 1.5;
    J2Response r;
    for (int it = 0; it < 200; ++it) {
      const double t = 0.5 * (lo + hi);
      m.respond({{{stretch(e), 0, 0}, {0, t, 0}, {0, 0, t}}}, s.data(), false, r);
      (r.P[1][1] > 0 ? hi : lo) = t;
    }
    m.respond({{{stretch(e), 0, 0}, {0, 0.5 * (lo + hi), 0}, {0, 0, 0.5 * (lo + hi)}}}, s.data(), false, r);
    work += r.plasticWork;
    next = r.state;
    s = next;
  }
  alpha = s[kJ2Alpha];
  return work;
}

TEST(J2PlasticityClosedForm, DissipatedWorkOfUniaxialFlow) {
  double alpha = 0.0;
  const double small = uniaxialPlasticWork(material(false), 0.02, 10, alpha);
  const double exact = kYield * alpha + 0.5 * kH * alpha * alpha;
  EXPECT_NEAR(small, exact, 1e-9 * exact);
  double a10 = 0.0, a20 = 0.0;
  const double w10 = uniaxialPlasticWork(material(true), 0.4, 10, a10);
  const double w20 = uniaxialPlasticWork(material(true), 0.4, 20, a20);
  const double e10 = std::abs(w10 - (kYield * a10 + 0.5 * kH * a10 * a10));
  const double e20 = std::abs(w20 - (kYield * a20 + 0.5 * kH * a20 * a20));
  EXPECT_GT(e10 / e20, 3.0) << "errors " << e10 << ", " << e20 << " of " << w20;  // second order
  EXPECT_LT(e20, 1e-3 * w20);
}

// In small strain the increment's work is 1/2 (sigma_n + sigma) : d eps_p, never negative, also
// when the flow reverses within the increment.
TEST(J2Plasticity, SmallStrainIncrementWorkIsTheTrapezoidOfThePlasticStrain) {
  const J2Plasticity m = material(false);
  const auto s1 = flowedState(m, kGeneral);
  Mat3 F = kGeneral;  // reverse the shear and the stretch past reverse yield
  F[0][1] = -F[0][1], F[1][0] = -F[1][0], F[0][0] = 2 - F[0][0];
  J2Response r;
  m.respond(F, s1.data(), false, r);
  ASSERT_TRUE(r.yielded);
  double expected = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = i == j ? i : (i + j == 1 ? 3 : (i + j == 3 ? 4 : 5));  // the state's pair of (i, j)
      const double deps = r.state[size_t(k)] - s1[size_t(k)];
      expected += 0.5 * (s1[size_t(kJ2Stress + 3 * i + j)] + r.P[i][j]) * deps;
    }
  EXPECT_NEAR(r.plasticWork, expected, 1e-9 * std::abs(expected));
  EXPECT_GT(r.plasticWork, 0.0);
}

// The finite-strain consistent tangent is symmetric (dP_iJ/dF_kL = dP_kL/dF_iJ): the return
// map of associative J2 flow with the exponential map derives from an incremental potential.
TEST(J2Plasticity, FiniteStrainTangentIsSymmetric) {
  const J2Plasticity m = material(true);
  J2Response r;
  m.respond(kLarge, flowedState(m, kGeneral).data(), true, r);
  ASSERT_TRUE(r.yielded);
  double norm = 0.0, asym = 0.0;
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) norm += r.A[a][b] * r.A[a][b], asym += std::pow(r.A[a][b] - r.A[b][a], 2);
  EXPECT_LT(std::sqrt(asym), 1e-12 * std::sqrt(norm));
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// The elastic tangent of a yielding point (the explicit critical step's stiffness): in small
// strain the elasticity tensor itself; in finite strain at least as stiff as the consistent
// tangent along every direction tried (dP : A : dP for the unit directions of F).
TEST(J2Plasticity, ElasticTangentOfAYieldingPoint) {
  const J2Plasticity small = material(false);
  J2Response r;
  small.respond(kGeneral, small.initialState().data(), true, r, true);
  ASSERT_TRUE(r.yielded);
  const double K = small.bulkModulus(), mu = small.shearModulus();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          const double dd = (i == j) * (k == l), sym = 0.5 * ((i == k) * (j == l) + (i == l) * (j == k));
          EXPECT_NEAR(r.A[3 * i + j][3 * k + l], K * dd + 2 * mu * (sym - dd / 3), 1e-9 * kE);
        }
  const J2Plasticity finite = material(true);
  J2Response consistent, elastic;
  finite.respond(kLarge, finite.initialState().data(), true, consistent);
  finite.respond(kLarge, finite.initialState().data(), true, elastic, true);
  ASSERT_TRUE(consistent.yielded);
  bool stiffer = false;
  for (int a = 0; a < 9; ++a) {
    EXPECT_GE(elastic.A[a][a], consistent.A[a][a] * (1 - 1e-12)) << "direction " << a;
    stiffer = stiffer || elastic.A[a][a] > consistent.A[a][a] * (1 + 1e-3);
  }
  EXPECT_TRUE(stiffer);
}

}  // namespace
}  // namespace choc
