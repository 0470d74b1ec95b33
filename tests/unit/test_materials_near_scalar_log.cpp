// The explicit finite-strain J2 update without principal axes (materials/NearScalarLog.hpp):
// the series' logarithm and exponential against the principal-axis ones, and J2Plasticity's
// response without its tangent (series) against the one with it (principal axes) at elastic,
// yielding and far-from-scalar states.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "materials/J2Plasticity.hpp"
#include "materials/NearScalarLog.hpp"
#include "materials/SymmetricEigen.hpp"

namespace choc {
namespace {

// Q diag(x) Q^T with Q a rotation from three angles.
Mat3 withAxes(const double* x, double a, double b, double c) {
  const Mat3 R1 = {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
  const Mat3 R2 = {{{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}}};
  const Mat3 R3 = {{{std::cos(c), 0, std::sin(c)}, {0, 1, 0}, {-std::sin(c), 0, std::cos(c)}}};
  const Mat3 Q = multiply(multiply(R1, R2), R3);
  Mat3 D{};
  for (int A = 0; A < 3; ++A) D[A][A] = x[A];
  return multiply(multiply(Q, D), transpose(Q));
}

double largestDifference(const Mat3& a, const Mat3& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(a[i][j] - b[i][j]));
  return d;
}

// log bbar and ln det b of b = Q diag(s e^l) Q^T, l traceless, are Q diag(l) Q^T and 3 ln s,
// to round-off: the series is exact beyond 1e-17 of ||z||, and b's entries carry eps.
TEST(NearScalarLog, LogarithmOfKnownSpectra) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> angle(0.0, 6.3), unit(-1.0, 1.0);
  for (double size : {0.0, 1e-6, 1e-3, 1e-2, 0.05, 0.14}) {  // ||z||_F up to about 0.2
    for (int trial = 0; trial < 20; ++trial) {
      double l[3] = {size * unit(gen), size * unit(gen), 0.0};
      l[2] = -l[0] - l[1];
      const double s = 1.0 + 0.1 * unit(gen);
      const double x[3] = {s * std::exp(l[0]), s * std::exp(l[1]), s * std::exp(l[2])};
      const double a = angle(gen), b = angle(gen), c = angle(gen);
      Mat3 logBar;
      double lnDet = 0.0;
      ASSERT_TRUE(logNearScalar(withAxes(x, a, b, c), logBar, lnDet)) << "||l|| about " << size;
      EXPECT_NEAR(lnDet, 3 * std::log(s), 1e-14);
      EXPECT_LE(largestDifference(logBar, withAxes(l, a, b, c)), 1e-14) << "||l|| about " << size;
    }
  }
}

// Too far from a multiple of I (||z||_F > 0.25: l = (1, -1, 0) gives tanh(1/2) sqrt 2 = 0.65), or
// not positive: refused, nothing written.
TEST(NearScalarLog, RefusesFarFromScalarOrNotPositive) {
  const double x[3] = {std::exp(1.0), std::exp(-1.0), 1.0};
  Mat3 logBar = identity3();
  double lnDet = 7.0;
  EXPECT_FALSE(logNearScalar(withAxes(x, 0.3, 0.2, 0.1), logBar, lnDet));
  EXPECT_EQ(logBar, identity3());
  EXPECT_EQ(lnDet, 7.0);
  const double negative[3] = {-1.0, 1.0, 1.0};
  EXPECT_FALSE(logNearScalar(withAxes(negative, 0.3, 0.2, 0.1), logBar, lnDet));
}

// exp of Q diag(y) Q^T is Q diag(e^y) Q^T, to a few eps of its entries (at most e^|y|): the
// series is summed beyond 1e-17, each entry of the reference carries a few eps from Q.
TEST(NearScalarLog, ExponentialOfKnownSpectra) {
  std::mt19937 gen(12);
  std::uniform_real_distribution<double> angle(0.0, 6.3), unit(-1.0, 1.0);
  for (double size : {0.0, 1e-5, 1e-2, 0.3, 0.55}) {
    for (int trial = 0; trial < 20; ++trial) {
      const double y[3] = {size * unit(gen), size * unit(gen), size * unit(gen)};
      const double ey[3] = {std::exp(y[0]), std::exp(y[1]), std::exp(y[2])};
      const double a = angle(gen), b = angle(gen), c = angle(gen);
      EXPECT_LE(largestDifference(expSmall(withAxes(y, a, b, c)), withAxes(ey, a, b, c)),
                6 * 2.2e-16 * std::exp(size))
          << "||y|| about " << size;
    }
  }
}

constexpr double kE = 117e9, kNu = 0.35, kYield = 400e6, kH = 100e6;  // the Taylor bar's copper

// The response without the tangent (the series) against the one with it (the principal axes):
// P, the whole state and the energy. Both compute the same formulas. Either knows the
// logarithmic strain of a stretch near 1 to a few eps absolutely (b_e's entries are of size 1),
// so the stresses agree to 50 eps (2 mu + 3 kappa) (5e-3 Pa for copper, where P is 1e8 to 1e9
// Pa: a series term missing at ||e|| = 1e-3 would err by 1e2 Pa), the stored energy mu ||e||^2
// to 2 mu ||e|| times that strain error (||e|| <= 0.01 here), and the rest of the state (b_e's
// inverse plastic stretch, alpha, F, the temperature) to 1e-13 of its size.
void expectSameResponse(const J2Plasticity& m, const Mat3& F, const double* old, bool yields) {
  const double eps = 2.2e-16, mu = kE / (2 * (1 + kNu)), kappa = kE / (3 * (1 - 2 * kNu));
  const double stress = 50 * eps * (2 * mu + 3 * kappa), energy = 2 * mu * 0.01 * 50 * eps;
  J2Response series, axes;
  m.respond(F, old, false, series, false, 1e-8);
  m.respond(F, old, true, axes, false, 1e-8);
  ASSERT_EQ(series.yielded, yields);
  ASSERT_EQ(axes.yielded, yields);
  EXPECT_LE(largestDifference(series.P, axes.P), stress);
  EXPECT_LE(largestDifference(series.cauchy, axes.cauchy), 2 * stress);
  for (int k = 0; k < kJ2StateSize; ++k) {
    const bool isStress = k >= kJ2Stress && k < kJ2Stress + 9;
    const double tol = isStress ? stress : k == kJ2Energy ? energy : 1e-13 * std::max(1.0, std::abs(axes.state[size_t(k)]));
    EXPECT_NEAR(series.state[size_t(k)], axes.state[size_t(k)], tol) << "state entry " << k;
  }
  EXPECT_NEAR(series.energy, axes.energy, energy);
  EXPECT_NEAR(series.plasticWork, axes.plasticWork, stress);
}

TEST(NearScalarLog, J2ResponseWithoutAxesIsTheResponseWithThem) {
  {
    const J2Plasticity m(linearHardening(kE, kNu, kYield, kH), true);
    const auto virgin = m.initialState();
    // Elastic: a small stretch and shear, turned.
    const double stretch[3] = {1.0009, 0.9996, 1.0001};
    const Mat3 Fe = multiply(withAxes(stretch, 0.4, 1.1, -0.7), Mat3{{{0.8, -0.6, 0}, {0.6, 0.8, 0}, {0, 0, 1}}});
    expectSameResponse(m, Fe, virgin.data(), false);
    // Yielding from the virgin state, then from a flowed state along another direction.
    const Mat3 F1 = {{{1.012, 0.004, -0.003}, {0.006, 0.993, 0.002}, {-0.001, 0.005, 1.001}}};
    expectSameResponse(m, F1, virgin.data(), true);
    J2Response flowed;
    m.respond(F1, virgin.data(), true, flowed);
    Mat3 F2 = F1;
    F2[0][1] += 0.01, F2[2][2] -= 0.008;
    expectSameResponse(m, F2, flowed.state.data(), true);
    // A large plastic deformation (the Taylor bar's impact face: stretches of 2 and 0.6) whose
    // elastic part stays small: b_e near a multiple of I.
    const Mat3 F3 = {{{2.0, 0.3, 0}, {0, 0.6, 0.1}, {0, 0, 0.85}}};
    expectSameResponse(m, F3, virgin.data(), true);
  }
}

// A material whose elastic strains are large (yield at E / 2): b_e far from a multiple of I, the
// series refused and the principal axes taken; the two responses are then the same code.
TEST(NearScalarLog, FarFromScalarFallsBackToTheAxes) {
  const J2Plasticity m(linearHardening(1e9, 0.3, 5e8, 1e8), true);
  const Mat3 F = {{{1.5, 0.2, 0}, {0, 0.7, 0}, {0, 0.1, 1.1}}};
  J2Response series, axes;
  m.respond(F, m.initialState().data(), false, series);
  m.respond(F, m.initialState().data(), true, axes);
  EXPECT_EQ(series.P, axes.P);
  EXPECT_EQ(series.state, axes.state);
}

}  // namespace
}  // namespace choc
