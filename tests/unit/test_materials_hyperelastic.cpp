// The hyperelastic materials at one point: the stress is the energy's derivative and the
// tangent the stress's (central differences, fd_tangent.hpp), and the neo-Hookean closed forms
// of uniaxial stretch and simple shear (BENCHMARKS.md section 13), written here from W alone.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "materials/Hyperelastic.hpp"

namespace choc {
namespace {

using test::Dense;

constexpr double kE = 2.0e11, kNu = 0.3;
const double kMu = kE / (2 * (1 + kNu)), kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));

// The six independent components of a symmetric E, (11, 22, 33, 12, 23, 31).
constexpr int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

Mat3 strainOf(const std::vector<double>& e) {
  Mat3 E{};
  for (int k = 0; k < 6; ++k) {
    E[kPair[k][0]][kPair[k][1]] = e[size_t(k)];
    E[kPair[k][1]][kPair[k][0]] = e[size_t(k)];
  }
  return E;
}

StressResponse respondAt(const HyperelasticMaterial& m, const std::vector<double>& e, bool tangent) {
  Mat3 C = strainOf(e);
  for (auto& row : C)
    for (double& v : row) v *= 2;
  for (int i = 0; i < 3; ++i) C[i][i] += 1;
  StressResponse r;
  m.respond(C, tangent, r);
  return r;
}

// A general strain state: stretches of 10-40 % with shear, J != 1.
const std::vector<double> kStrain = {0.21, -0.12, 0.08, 0.09, -0.05, 0.11};

class Hyperelastic : public ::testing::TestWithParam<std::string> {
 protected:
  std::shared_ptr<const HyperelasticMaterial> m = makeHyperelastic(GetParam(), kE, kNu);
  test::TangentCheckOptions options() const {
    test::TangentCheckOptions o;
    o.scale = 0.1;  // the strain over which the response varies
    return o;
  }
};

// dW/de_k: S_IJ for the normal components, 2 S_IJ for the shear ones (E_IJ and E_JI move).
TEST_P(Hyperelastic, StressIsTheDerivativeOfTheEnergy) {
  auto W = [&](const std::vector<double>& e) { return std::vector<double>{respondAt(*m, e, false).energy}; };
  const StressResponse r = respondAt(*m, kStrain, false);
  Dense J(1, 6);
  for (int k = 0; k < 6; ++k) J(0, k) = (k < 3 ? 1.0 : 2.0) * r.S[kPair[k][0]][kPair[k][1]];
  EXPECT_TRUE(test::tangentMatches(W, J, kStrain, options()));
  EXPECT_TRUE(test::tangentMismatches(W, test::perturbed(J), kStrain, options()));
}

TEST_P(Hyperelastic, TangentIsTheDerivativeOfTheStress) {
  auto S = [&](const std::vector<double>& e) {
    const StressResponse r = respondAt(*m, e, false);
    std::vector<double> s(6);
    for (int k = 0; k < 6; ++k) s[size_t(k)] = r.S[kPair[k][0]][kPair[k][1]];
    return s;
  };
  const StressResponse r = respondAt(*m, kStrain, true);
  Dense J(6, 6);
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      const auto& t = r.tangent[kPair[a][0]][kPair[a][1]];
      J(a, b) = b < 3 ? t[kPair[b][0]][kPair[b][1]] : t[kPair[b][0]][kPair[b][1]] + t[kPair[b][1]][kPair[b][0]];
    }
  EXPECT_TRUE(test::tangentMatches(S, J, kStrain, options()));
  EXPECT_TRUE(test::tangentMismatches(S, test::perturbed(J), kStrain, options()));
}

// At C = I: no stress, and the tangent is the linear elastic one of the same E and nu.
TEST_P(Hyperelastic, TheUndeformedStateIsLinearElastic) {
  const StressResponse r = respondAt(*m, std::vector<double>(6, 0.0), true);
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J) {
      EXPECT_NEAR(r.S[I][J], 0.0, 1e-12 * kE);
      for (int K = 0; K < 3; ++K)
        for (int L = 0; L < 3; ++L) {
          const double linear = kLambda * (I == J) * (K == L) + kMu * ((I == K) * (J == L) + (I == L) * (J == K));
          EXPECT_NEAR(r.tangent[I][J][K][L], linear, 1e-12 * kE);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Models, Hyperelastic, ::testing::Values("Saint Venant-Kirchhoff", "neo-Hookean"),
                         [](const auto& info) { return info.param == "neo-Hookean" ? "NeoHookean" : "SaintVenantKirchhoff"; });

// P = F S for a diagonal or general F.
Mat3 firstPiola(const HyperelasticMaterial& m, const Mat3& F) {
  StressResponse r;
  m.respond(transposeTimes(F), false, r);
  return multiply(F, r.S);
}

// Uniaxial stretch lambda = 2 of W = mu/2 (I1 - 3) - mu ln J + Lambda/2 (ln J)^2 with free
// lateral faces: F = diag(l, t, t), J = l t^2, and the lateral nominal stress
//   P22 = (mu (t^2 - 1) + Lambda ln J) / t = 0
// fixes t (bisection here, monotone in t); then P11 = mu (l - 1/l) + Lambda ln J / l.
TEST(NeoHookeanClosedForm, UniaxialStretchToTwo) {
  const auto m = makeHyperelastic("neo-Hookean", kE, kNu);
  const double l = 2.0;
  auto lateral = [&](double t) { return kMu * (t * t - 1) + kLambda * std::log(l * t * t); };
  double lo = 0.1, hi = 1.0;  // lateral(0.1) < 0 < lateral(1)
  for (int k = 0; k < 200; ++k) (lateral(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
  const double t = 0.5 * (lo + hi), J = l * t * t;
  const double nominal = kMu * (l - 1 / l) + kLambda * std::log(J) / l;
  const Mat3 P = firstPiola(*m, {{{l, 0, 0}, {0, t, 0}, {0, 0, t}}});
  EXPECT_NEAR(P[0][0], nominal, 1e-12 * nominal);
  EXPECT_NEAR(P[1][1], 0.0, 1e-12 * nominal);
  EXPECT_NEAR(P[2][2], 0.0, 1e-12 * nominal);
  EXPECT_GT(nominal, 1.0 * kMu);  // a finite-strain value, not the linear E (l - 1) = 2.6 mu
}

// Simple shear F = I + gamma e1 (x) e2: J = 1, b = F F^T, sigma = mu (b - I):
//   sigma12 = mu gamma, sigma11 = mu gamma^2 (the Poynting effect), sigma22 = sigma33 = 0.
TEST(NeoHookeanClosedForm, SimpleShear) {
  const auto m = makeHyperelastic("neo-Hookean", kE, kNu);
  for (double gamma : {0.1, 0.5, 1.0}) {
    const Mat3 F = {{{1, gamma, 0}, {0, 1, 0}, {0, 0, 1}}};
    StressResponse r;
    m->respond(transposeTimes(F), false, r);
    const Mat3 s = cauchyStress(F, r.S);
    const double tol = 1e-12 * kMu;
    EXPECT_NEAR(s[0][1], kMu * gamma, tol);
    EXPECT_NEAR(s[1][0], kMu * gamma, tol);
    EXPECT_NEAR(s[0][0], kMu * gamma * gamma, tol);
    EXPECT_NEAR(s[1][1], 0.0, tol);
    EXPECT_NEAR(s[2][2], 0.0, tol);
    EXPECT_NEAR(s[0][2], 0.0, tol);
    EXPECT_NEAR(s[1][2], 0.0, tol);
  }
}

TEST(NeoHookeanClosedForm, AnInvertedPointIsRefused) {
  const auto m = makeHyperelastic("neo-Hookean", kE, kNu);
  StressResponse r;
  Mat3 C = identity3();
  C[2][2] = 0.0;  // det C = 0
  EXPECT_THROW(m->respond(C, false, r), std::domain_error);
}

TEST(HyperelasticModels, UnknownNamesAndConstantsAreRefused) {
  EXPECT_THROW(makeHyperelastic("Mooney-Rivlin", kE, kNu), std::invalid_argument);
  EXPECT_THROW(makeHyperelastic("neo-Hookean", -1.0, kNu), std::invalid_argument);
  EXPECT_THROW(makeHyperelastic("Saint Venant-Kirchhoff", kE, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace choc
