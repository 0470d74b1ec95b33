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
#include "fem/FiniteStrainSolid.hpp"
#include "fem/SolidElement.hpp"
#include "test_fem_solid_cases.hpp"

namespace choc {
namespace {

using test::ElementCase;

constexpr double kE = 1.0e3, kNu = 0.3;  // any consistent units

int componentsOf(const ElementCase& c) { return c.kinematics == Kinematics::ThreeD ? 3 : 2; }

// u_a = (F - I) (X_a - origin) on the components the kinematics carries.
std::vector<double> displacementOf(const ElementCase& c, const Mat3& F, const Point3& origin = {0, 0, 0}) {
  const int nc = componentsOf(c);
  std::vector<double> u;
  for (const Point3& X : c.x)
    for (int i = 0; i < nc; ++i) {
      double v = 0.0;
      for (int J = 0; J < 3; ++J) v += (F[i][J] - (i == J)) * (X[J] - origin[J]);
      u.push_back(v);
    }
  return u;
}

// A stretch with shear in the kinematics' plane(s), then (not axisymmetric) a rotation of
// 30 degrees about z: a general F with det F = 1.14.
Mat3 generalGradient(Kinematics k) {
  if (k == Kinematics::Axisymmetric) return {{{1.2, 0, 0}, {0, 0.85, 0}, {0, 0, 1.2}}};
  const Mat3 U = k == Kinematics::ThreeD ? Mat3{{{1.2, 0.15, -0.1}, {0.05, 0.9, 0.2}, {0.1, -0.05, 1.1}}}
                                         : Mat3{{{1.2, 0.15, 0}, {0.05, 0.9, 0}, {0, 0, 1}}};
  const double a = std::acos(-1.0) / 6;
  const Mat3 R = {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
  return multiply(R, U);
}

// A rotation by angle about an axis (about z in 2D).
Mat3 rotation(Kinematics k, double angle) {
  Point3 n = k == Kinematics::ThreeD ? Point3{0.3, -0.5, 0.81} : Point3{0, 0, 1};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= len;
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3 R{};
  const double K[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[i][j] = c * (i == j) + s * K[i][j] + (1 - c) * n[i] * n[j];
  return R;
}

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
