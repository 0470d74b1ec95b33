// The total Lagrangian continuum kernel on every element type and kinematics
// (test_fem_solid_cases.hpp): its tangent against central differences of its internal force,
// a homogeneous deformation reproduced exactly (the finite-strain patch test at one element),
// zero force and stress under rigid rotations of 90 and 180 degrees (which the small-strain
// kernel fails), and inverted elements refused.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "finite_strain_states.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "fem/SolidElement.hpp"
#include "test_fem_solid_cases.hpp"

namespace choc {
namespace {

using test::ElementCase;

constexpr double kE = 1.0e3, kNu = 0.3;  // any consistent units

using test::componentsOf;
using test::displacementOf;
using test::generalGradient;
using test::rotation;
using test::checkPlasticTangent;

class FiniteStrain : public ::testing::TestWithParam<ElementCase> {
 protected:
  std::shared_ptr<const HyperelasticMaterial> neo = makeHyperelastic("neo-Hookean", kE, kNu);
  std::shared_ptr<const HyperelasticMaterial> svk = makeHyperelastic("Saint Venant-Kirchhoff", kE, kNu);
};

TEST_P(FiniteStrain, TangentMatchesCentralDifferencesOfTheInternalForce) {
  const ElementCase& c = GetParam();
  std::vector<double> u = displacementOf(c, generalGradient(c.kinematics));
  for (size_t j = 0; j < u.size(); ++j) u[j] += 0.02 * std::sin(1.7 * double(j) + 0.3);  // not homogeneous
  for (const auto& m : {neo, svk}) {
    const FiniteStrainSolid el(c.topology, c.kinematics, m);
    auto R = [&](const std::vector<double>& x) {
      std::vector<double> f;
      el.evaluate(c.x, x, f, nullptr);
      return f;
    };
    DenseMatrix K;
    std::vector<double> f;
    el.evaluate(c.x, u, f, &K);
    test::Dense J(K.rows(), K.cols());
    for (int i = 0; i < K.rows(); ++i)
      for (int j = 0; j < K.cols(); ++j) J(i, j) = K(i, j);
    test::TangentCheckOptions o;
    o.scale = 0.1;  // the element is about 1 long: its response varies over 0.1
    EXPECT_TRUE(test::tangentMatches(R, J, u, o)) << m->name();
    EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), u, o)) << m->name();
  }
}

// With x = F X the stress is the material's at F at every point, so the element's average
// Cauchy stress is sigma(F), and f_a = P_iJ int dN_a/dX_J dV gives sum_a f_a = 0 and
// sum_a f_ai X_aK = P_iK V (an isoparametric element reproduces X exactly). Axisymmetric
// elements take F = diag(l_r, l_z, l_r) (u_r = (l_r - 1) R), the homogeneous states a ring allows.
TEST_P(FiniteStrain, AHomogeneousDeformationIsReproducedExactly) {
  const ElementCase& c = GetParam();
  const Mat3 F = generalGradient(c.kinematics);
  const FiniteStrainSolid el(c.topology, c.kinematics, neo);
  const std::vector<double> u = displacementOf(c, F);
  StressResponse r;
  neo->respond(transposeTimes(F), false, r);
  const Mat3 s = cauchyStress(F, r.S), P = multiply(F, r.S);
  std::array<double, 6> sigma{};
  double w = 0.0;
  el.averageStress(c.x, u, sigma, w);
  const double tol = 1e-10 * kE;
  const double expected[6] = {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[2][0]};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(sigma[size_t(k)], expected[k], tol) << "component " << k;
  EXPECT_NEAR(w, r.energy, 1e-10 * kE);
  if (c.kinematics == Kinematics::Axisymmetric) return;
  std::vector<double> f;
  el.evaluate(c.x, u, f, nullptr);
  const int nc = componentsOf(c);
  for (int i = 0; i < nc; ++i) {
    double sum = 0.0;
    for (size_t a = 0; a < c.x.size(); ++a) sum += f[a * nc + i];
    EXPECT_NEAR(sum, 0.0, tol * c.measure);
    for (int K = 0; K < nc; ++K) {
      double moment = 0.0;
      for (size_t a = 0; a < c.x.size(); ++a) moment += f[a * nc + i] * c.x[a][K];
      EXPECT_NEAR(moment, P[i][K] * c.measure, tol * c.measure) << "i " << i << " K " << K;
    }
  }
}

// A rigid rotation by 90 or 180 degrees: no stress and no force to round-off. The small-strain
// kernel's K u is of the order of E there (its strain of a rotation is not zero): that is why
// 'Strain = small' is wrong for a part that turns. Axisymmetric rings can only turn about
// their axis (u = 0) or slide along it: that translation is checked instead.
TEST_P(FiniteStrain, RigidRotationsCreateNoStress) {
  const ElementCase& c = GetParam();
  const FiniteStrainSolid el(c.topology, c.kinematics, neo);
  const Point3 centre = {0.3, -0.2, 0.4};
  const bool axi = c.kinematics == Kinematics::Axisymmetric;
  for (double degrees : {90.0, 180.0}) {
    std::vector<double> u = displacementOf(c, rotation(c.kinematics, degrees * std::acos(-1.0) / 180), centre);
    if (axi)
      for (size_t a = 0; a < c.x.size(); ++a) u[2 * a] = 0.0, u[2 * a + 1] = degrees / 90;
    std::vector<double> f;
    el.evaluate(c.x, u, f, nullptr);
    for (double v : f) EXPECT_NEAR(v, 0.0, 1e-12 * kE) << degrees << " degrees";
    std::array<double, 6> sigma{};
    double w = 0.0;
    el.averageStress(c.x, u, sigma, w);
    for (double v : sigma) EXPECT_NEAR(v, 0.0, 1e-12 * kE);
    EXPECT_NEAR(w, 0.0, 1e-12 * kE);
    if (axi) continue;
    Material lin;
    lin.youngsModulus = kE, lin.poissonsRatio = kNu, lin.density = 1.0;
    DenseMatrix K;
    makeSolidElement(c.topology, c.kinematics, lin)->stiffness(c.x, K);
    double largest = 0.0;
    for (int i = 0; i < K.rows(); ++i) {
      double v = 0.0;
      for (int j = 0; j < K.cols(); ++j) v += K(i, j) * u[size_t(j)];
      largest = std::max(largest, std::abs(v));
    }
    EXPECT_GT(largest, 0.01 * kE * std::pow(c.measure, c.kinematics == Kinematics::ThreeD ? 2.0 / 3 : 0.5))
        << "small strain under a rotation of " << degrees << " degrees";
  }
}

// A reflection of y (det F = -1) is an inverted element, named as such.
TEST_P(FiniteStrain, AnInvertedElementIsRefused) {
  const ElementCase& c = GetParam();
  const FiniteStrainSolid el(c.topology, c.kinematics, svk);
  const std::vector<double> u = displacementOf(c, {{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}});
  std::vector<double> f;
  try {
    el.evaluate(c.x, u, f, nullptr);
    ADD_FAILURE() << "no error for det F = -1";
  } catch (const InvertedElement& e) {
    EXPECT_NE(std::string(e.what()).find("det F"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, FiniteStrain, ::testing::ValuesIn(test::allElementCases()),
                         [](const auto& info) { return info.param.label; });

}  // namespace
}  // namespace choc

namespace choc {
namespace {

using test::ElementCase;

// F-bar's elements: every one with more than one point (TET4 and TRI3 have one).
std::vector<ElementCase> fbarCases() {
  std::vector<ElementCase> cases;
  for (const ElementCase& c : test::allElementCases())
    if (c.topology != "TET4" && c.topology != "TRI3") cases.push_back(c);
  return cases;
}

class FBar : public ::testing::TestWithParam<ElementCase> {};

// F-bar's force is the derivative of int W(Fbar) dV (the energy evaluate returns): central
// differences of that energy, at a state that is not homogeneous (J varies over the element).
TEST_P(FBar, ForceIsTheDerivativeOfTheElementEnergy) {
  const ElementCase& c = GetParam();
  std::vector<double> u = displacementOf(c, generalGradient(c.kinematics));
  for (size_t j = 0; j < u.size(); ++j) u[j] += 0.02 * std::sin(1.7 * double(j) + 0.3);
  const FiniteStrainSolid el(c.topology, c.kinematics, makeHyperelastic("neo-Hookean", kE, kNu), true);
  test::expectForceIsTheEnergysDerivative(el, c, u);
  std::vector<double> f;
  el.evaluate(c.x, u, f, nullptr);
  // The standard element's force differs there: F-bar changes the element.
  const FiniteStrainSolid standard(c.topology, c.kinematics, makeHyperelastic("neo-Hookean", kE, kNu));
  std::vector<double> fs;
  standard.evaluate(c.x, u, fs, nullptr);
  double diff = 0.0, norm = 0.0;
  for (size_t k = 0; k < f.size(); ++k) diff += std::pow(f[k] - fs[k], 2), norm += f[k] * f[k];
  EXPECT_GT(std::sqrt(diff), 1e-3 * std::sqrt(norm));
}

// Under a homogeneous deformation J is the centre's everywhere: F-bar is the standard element.
TEST_P(FBar, HomogeneousDeformationIsTheStandardElements) {
  const ElementCase& c = GetParam();
  const std::vector<double> u = displacementOf(c, generalGradient(c.kinematics));
  const auto m = makeHyperelastic("neo-Hookean", kE, kNu);
  std::vector<double> f, fs;
  FiniteStrainSolid(c.topology, c.kinematics, m, true).evaluate(c.x, u, f, nullptr);
  FiniteStrainSolid(c.topology, c.kinematics, m).evaluate(c.x, u, fs, nullptr);
  double scale = 0.0;
  for (double v : fs) scale = std::max(scale, std::abs(v));
  for (size_t k = 0; k < f.size(); ++k) EXPECT_NEAR(f[k], fs[k], 1e-12 * scale);
}

// F-bar's consistent tangent (FBarTangent.hpp) against central differences of its force, where
// J varies over the element: neo-Hookean (a symmetric tangent, the energy's second derivative)
// and J2 from a yielded committed state (the algorithmic tangent: symmetric too). The standard
// element's tangent at Fbar, which F-bar gave before, fails the same check.
TEST_P(FBar, TangentMatchesCentralDifferencesOfTheForce) {
  const ElementCase& c = GetParam();
  std::vector<double> u = displacementOf(c, generalGradient(c.kinematics));
  for (size_t j = 0; j < u.size(); ++j) u[j] += 0.02 * std::sin(1.7 * double(j) + 0.3);
  const FiniteStrainSolid el(c.topology, c.kinematics, makeHyperelastic("neo-Hookean", kE, kNu), true);
  const ElementGeometry g = el.geometry(c.x);
  auto R = [&](const std::vector<double>& x) {
    std::vector<double> r;
    el.evaluate(g, x, r, nullptr);
    return r;
  };
  std::vector<double> f;
  DenseMatrix K, Kstd;
  el.evaluate(g, u, f, &K);
  el.evaluate(g, u, f, &Kstd, nullptr, nullptr, nullptr, true);  // the standard element's at Fbar
  test::Dense J(K.rows(), K.cols()), Jstd(K.rows(), K.cols());
  double asym = 0.0, norm = 0.0;
  for (int i = 0; i < K.rows(); ++i)
    for (int j = 0; j < K.cols(); ++j) {
      J(i, j) = K(i, j), Jstd(i, j) = Kstd(i, j);
      asym = std::max(asym, std::abs(K(i, j) - K(j, i))), norm = std::max(norm, std::abs(K(i, j)));
    }
  test::TangentCheckOptions o;
  o.scale = 0.1;
  EXPECT_TRUE(test::tangentMatches(R, J, u, o));
  EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), u, o));
  EXPECT_TRUE(test::tangentMismatches(R, Jstd, u, o));
  EXPECT_LE(asym, 1e-12 * norm);  // round-off of entries of size norm
}

TEST_P(FBar, PlasticTangentMatchesCentralDifferencesOfTheForce) {
  const ElementCase& c = GetParam();
  const auto m = std::make_shared<const J2Plasticity>(linearHardening(kE, kNu, kE / 200, kE / 20), true);
  const double asymmetry = checkPlasticTangent(FiniteStrainSolid(c.topology, c.kinematics, m, true), c, 0.004, "");
  EXPECT_LE(asymmetry, 1e-12);  // J2's algorithmic tangent has the major symmetry: so has F-bar's
}

INSTANTIATE_TEST_SUITE_P(Elements, FBar, ::testing::ValuesIn(fbarCases()),
                         [](const auto& info) { return info.param.label; });

TEST(FBarRefused, OnOnePointElementsAndInSmallStrain) {
  const auto m = makeHyperelastic("neo-Hookean", kE, kNu);
  EXPECT_THROW(FiniteStrainSolid("TET4", Kinematics::ThreeD, m, true), std::invalid_argument);
  EXPECT_THROW(FiniteStrainSolid("TRI3", Kinematics::PlaneStrain, m, true), std::invalid_argument);
  EXPECT_NO_THROW(FiniteStrainSolid("TET10", Kinematics::ThreeD, m, true));
  const auto small = std::make_shared<const J2Plasticity>(linearHardening(kE, kNu, 1.0, 0.0), false);
  EXPECT_THROW(FiniteStrainSolid("HEX8", Kinematics::ThreeD, small, true), std::invalid_argument);
}

// The plastic element (J2, small and finite strain) on every element type: its tangent against
// central differences of its force, from a yielded committed state (the points' states after a
// first deformation), in the plastic branch.
class PlasticElement : public ::testing::TestWithParam<ElementCase> {};

TEST_P(PlasticElement, TangentMatchesCentralDifferencesOfTheInternalForce) {
  const ElementCase& c = GetParam();
  for (bool finite : {false, true}) {
    // sigma_y = E / 200: the state below strains the element by several times its yield strain
    const auto m = std::make_shared<const J2Plasticity>(linearHardening(kE, kNu, kE / 200, kE / 20), finite);
    checkPlasticTangent(FiniteStrainSolid(c.topology, c.kinematics, m), c, 0.0, finite ? "finite" : "small");
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, PlasticElement, ::testing::ValuesIn(test::allElementCases()),
                         [](const auto& info) { return info.param.label; });

}  // namespace
}  // namespace choc
