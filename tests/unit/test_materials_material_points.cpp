// Every material law as a material point (materials/MaterialPoint.hpp), built through the law
// registry from validated keys as an input would: P is the derivative of the energy W(F) and A
// the derivative of P (central differences, fd_tangent.hpp), at rest each law is the linear
// elastic material of its constants. The Mooney-Rivlin rubber against its closed forms
// (MooneyRivlin.cpp): the isochoric uniaxial, equibiaxial and simple-shear stress differences
// of the incompressible law and the bulk response to a pure dilatation.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Errors.hpp"
#include "fd_tangent.hpp"
#include "input/Validation.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {
namespace {

using test::Dense;

constexpr double kE = 2.0e11, kNu = 0.3;
constexpr double kC10 = 0.4e6, kC01 = 0.1e6, kBulk = 50e6;  // a rubber: mu = 1 MPa, K = 50 MPa

// The material's keys, validated against the declarations (defaults filled in as in a run).
Teuchos::ParameterList keysOf(const std::string& law) {
  Teuchos::ParameterList valid, user;
  declareMaterialLaws(valid);
  user.set("Model", law);
  user.set("Density", 1000.0);
  if (law == "Mooney-Rivlin") {
    user.set("Mooney-Rivlin C10", kC10), user.set("Mooney-Rivlin C01", kC01), user.set("Bulk Modulus", kBulk);
  } else {
    user.set("Young's Modulus", kE), user.set("Poisson's Ratio", kNu);
  }
  if (law == "J2 plasticity") user.set("Yield Stress", kE / 200), user.set("Hardening Modulus", kE / 20);
  if (law == "Johnson-Cook") {
    user.set("Johnson-Cook A", kE / 200), user.set("Johnson-Cook B", kE / 50), user.set("Johnson-Cook n", 0.5);
    user.set("Melting Temperature", 1083.0), user.set("Specific Heat", 385.0);
  }
  validate(user, valid, {"test.xml", "Model/Materials/m"});
  return user;
}

std::shared_ptr<const MaterialPoint> pointOf(const std::string& law, bool finite) {
  const Teuchos::ParameterList keys = keysOf(law);
  checkMaterialKeys("test.xml", "m", keys);
  return materialLaw(law).point(LawInput{"test.xml", "Model/Materials/m/", keys, "B"}, finite);
}

Mat3 matrixOf(const std::vector<double>& f) {
  Mat3 F;
  for (int k = 0; k < 9; ++k) F[k / 3][k % 3] = f[size_t(k)];
  return F;
}

// A general deformation: stretches of 5-20 % with shear, J != 1.
const std::vector<double> kF = {1.12, 0.05, -0.03, 0.04, 0.93, 0.06, -0.02, 0.03, 1.07};

struct LawCase {
  std::string law;
  bool finite;
};

class MaterialPoints : public ::testing::TestWithParam<LawCase> {
 protected:
  std::shared_ptr<const MaterialPoint> m = pointOf(GetParam().law, GetParam().finite);
  std::vector<double> old() const {
    std::vector<double> s(size_t(m->stateSize()));
    if (!s.empty()) m->initialState(s.data());
    return s;
  }
  PointResponse at(const std::vector<double>& f, bool tangent) const {
    PointResponse r;
    const std::vector<double> s = old();
    m->respond(matrixOf(f), s.empty() ? nullptr : s.data(), nullptr, PointRequest{tangent, false, 0.0}, r);
    return r;
  }
  test::TangentCheckOptions options() const {
    test::TangentCheckOptions o;
    o.scale = 0.1;
    return o;
  }
};

// An elastic law's P is dW/dF (a plastic law's stored energy is not its potential).
class ElasticMaterialPoints : public MaterialPoints {};

TEST_P(ElasticMaterialPoints, StressIsTheDerivativeOfTheEnergy) {
  ASSERT_FALSE(m->dissipative());
  auto W = [&](const std::vector<double>& f) { return std::vector<double>{at(f, false).energy}; };
  const PointResponse r = at(kF, false);
  Dense J(1, 9);
  for (int k = 0; k < 9; ++k) J(0, k) = r.P[k / 3][k % 3];
  EXPECT_TRUE(test::tangentMatches(W, J, kF, options()));
  EXPECT_TRUE(test::tangentMismatches(W, test::perturbed(J), kF, options()));
}

TEST_P(MaterialPoints, TangentIsTheDerivativeOfTheStress) {
  auto P = [&](const std::vector<double>& f) {
    const PointResponse r = at(f, false);
    std::vector<double> p(9);
    for (int k = 0; k < 9; ++k) p[size_t(k)] = r.P[k / 3][k % 3];
    return p;
  };
  const PointResponse r = at(kF, true);
  Dense J(9, 9);
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) J(a, b) = r.A[a][b];
  EXPECT_TRUE(test::tangentMatches(P, J, kF, options()));
  EXPECT_TRUE(test::tangentMismatches(P, test::perturbed(J), kF, options()));
}

// Objectivity of the finite-strain laws: a rigid rotation Q after F rotates P, P(QF) = Q P(F), and
// leaves W (from a virgin state: a plastic point's state then depends on F alone). The small-strain
// laws are not objective (their strain sym(F - I) sees the rotation), and are not held to it.
class FiniteMaterialPoints : public MaterialPoints {};

TEST_P(FiniteMaterialPoints, ResponseIsObjective) {
  ASSERT_TRUE(m->finiteStrain());
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Mat3 Q = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  const Mat3 QF = multiply(Q, matrixOf(kF));
  const PointResponse r = at(kF, false);
  std::vector<double> qf(9);
  for (int k = 0; k < 9; ++k) qf[size_t(k)] = QF[k / 3][k % 3];
  const PointResponse rq = at(qf, false);
  const Mat3 QP = multiply(Q, r.P);
  double scale = 0.0;
  for (const auto& row : r.P)
    for (double v : row) scale = std::max(scale, std::abs(v));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(rq.P[i][j], QP[i][j], 1e-10 * scale) << i << j;
  EXPECT_NEAR(rq.energy, r.energy, 1e-10 * std::abs(r.energy));
}

// At F = I: no stress and the linear elastic tangent of the law's own constants.
TEST_P(MaterialPoints, TheUndeformedStateIsLinearElastic) {
  const ElasticConstants c = materialLaw(GetParam().law).elasticConstants(keysOf(GetParam().law));
  const double mu = c.youngsModulus / (2 * (1 + c.poissonsRatio));
  const double lambda = c.youngsModulus * c.poissonsRatio / ((1 + c.poissonsRatio) * (1 - 2 * c.poissonsRatio));
  const PointResponse r = at({1, 0, 0, 0, 1, 0, 0, 0, 1}, true);
  const double tol = 1e-9 * (lambda + 2 * mu);
  EXPECT_NEAR(m->modulus(), lambda + 2 * mu, tol);
  for (int a = 0; a < 9; ++a) {
    EXPECT_NEAR(r.P[a / 3][a % 3], 0.0, tol);
    for (int b = 0; b < 9; ++b) {
      const int i = a / 3, J = a % 3, k = b / 3, L = b % 3;
      const double linear = lambda * (i == J) * (k == L) + mu * ((i == k) * (J == L) + (i == L) * (J == k));
      EXPECT_NEAR(r.A[a][b], linear, tol) << a << " " << b;
    }
  }
}

std::string caseName(const ::testing::TestParamInfo<LawCase>& info) {
  std::string n;
  for (char ch : info.param.law)
    if (std::isalnum(static_cast<unsigned char>(ch))) n += ch;
  return n + (info.param.finite ? "Finite" : "Small");
}

void PrintTo(const LawCase& c, std::ostream* os) { *os << c.law << (c.finite ? " (finite)" : " (small)"); }

const LawCase kElastic[] = {{"linear elastic", false}, {"Saint Venant-Kirchhoff", true}, {"neo-Hookean", true},
                            {"Mooney-Rivlin", true}};
const LawCase kPlastic[] = {{"J2 plasticity", true}, {"J2 plasticity", false}, {"Johnson-Cook", true}};

INSTANTIATE_TEST_SUITE_P(Elastic, ElasticMaterialPoints, ::testing::ValuesIn(kElastic), caseName);
INSTANTIATE_TEST_SUITE_P(Elastic, MaterialPoints, ::testing::ValuesIn(kElastic), caseName);
INSTANTIATE_TEST_SUITE_P(Plastic, MaterialPoints, ::testing::ValuesIn(kPlastic), caseName);
const LawCase kFinite[] = {{"Saint Venant-Kirchhoff", true}, {"neo-Hookean", true}, {"Mooney-Rivlin", true},
                           {"J2 plasticity", true}, {"Johnson-Cook", true}};
INSTANTIATE_TEST_SUITE_P(Finite, FiniteMaterialPoints, ::testing::ValuesIn(kFinite), caseName);

Mat3 cauchyOf(const MaterialPoint& m, const Mat3& F) {
  PointResponse r;
  m.respond(F, nullptr, nullptr, PointRequest{}, r);
  return cauchyFromFirstPiola(r.P, F, true);
}

// Isochoric stretches and shear (J = 1: the bulk term vanishes), the incompressible closed forms.
TEST(MooneyRivlinClosedForm, IsochoricStressDifferences) {
  const auto m = pointOf("Mooney-Rivlin", true);
  const double tol = 1e-9 * 2 * (kC10 + kC01);
  for (double l : {0.7, 1.3, 2.0, 3.0}) {
    const double t = 1 / std::sqrt(l);
    const Mat3 uni = cauchyOf(*m, {{{l, 0, 0}, {0, t, 0}, {0, 0, t}}});
    EXPECT_NEAR(uni[0][0] - uni[1][1], 2 * (l * l - 1 / l) * (kC10 + kC01 / l), tol * l * l) << l;
    EXPECT_NEAR(uni[1][1], uni[2][2], tol) << l;
    const Mat3 bi = cauchyOf(*m, {{{l, 0, 0}, {0, l, 0}, {0, 0, 1 / (l * l)}}});
    EXPECT_NEAR(bi[0][0] - bi[2][2], 2 * (l * l - std::pow(l, -4)) * (kC10 + kC01 * l * l), tol * std::pow(l, 4)) << l;
  }
  for (double gamma : {0.1, 0.5, 1.0, 2.0}) {
    const Mat3 s = cauchyOf(*m, {{{1, gamma, 0}, {0, 1, 0}, {0, 0, 1}}});
    EXPECT_NEAR(s[0][1], 2 * gamma * (kC10 + kC01), tol) << gamma;
    EXPECT_NEAR(s[0][2], 0.0, tol) << gamma;
    EXPECT_NEAR(s[1][2], 0.0, tol) << gamma;
  }
}

// F = s I: the isochoric invariants stay 3, sigma = K (J - 1) I.
TEST(MooneyRivlinClosedForm, PureDilatationIsTheBulkResponse) {
  const auto m = pointOf("Mooney-Rivlin", true);
  for (double s : {0.9, 0.98, 1.05}) {
    const Mat3 c = cauchyOf(*m, {{{s, 0, 0}, {0, s, 0}, {0, 0, s}}});
    const double J = s * s * s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(c[i][j], i == j ? kBulk * (J - 1) : 0.0, 1e-9 * kBulk) << s;
  }
}

// A collapsed point (det C = 0; the element refuses det F <= 0 before the law sees C = F^T F).
TEST(MooneyRivlinClosedForm, ACollapsedPointIsRefused) {
  const auto m = pointOf("Mooney-Rivlin", true);
  PointResponse r;
  EXPECT_THROW(m->respond({{{1, 0, 0}, {0, 1, 0}, {0, 0, 0}}}, nullptr, nullptr, PointRequest{}, r), std::domain_error);
}

// Each law reads only its keys: E on the rubber, C10 on steel, and a missing bulk modulus are refused.
TEST(MaterialLaws, EachLawReadsOnlyItsKeys) {
  Teuchos::ParameterList rubber = keysOf("Mooney-Rivlin");
  rubber.set("Young's Modulus", 1e6);
  EXPECT_THROW(checkMaterialKeys("test.xml", "m", rubber), InputError);
  Teuchos::ParameterList steel = keysOf("neo-Hookean");
  steel.set("Mooney-Rivlin C10", 1e6);
  try {
    checkMaterialKeys("test.xml", "m", steel);
    ADD_FAILURE() << "C10 on a neo-Hookean material was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'Model' = 'Mooney-Rivlin'?"), std::string::npos) << e.what();
  }
  Teuchos::ParameterList valid, noBulk;
  declareMaterialLaws(valid);
  noBulk.set("Model", std::string("Mooney-Rivlin")), noBulk.set("Density", 1000.0), noBulk.set("Mooney-Rivlin C10", kC10);
  validate(noBulk, valid, {"test.xml", "Model/Materials/m"});
  EXPECT_THROW(checkMaterialKeys("test.xml", "m", noBulk), InputError);
}

TEST(MaterialLaws, EveryLawIsListedOnceByItsName) {
  std::vector<std::string> names;
  for (const MaterialLaw* law : materialLaws()) {
    EXPECT_EQ(&materialLaw(law->name()), law);
    EXPECT_EQ(std::count(names.begin(), names.end(), law->name()), 0) << law->name();
    names.push_back(law->name());
    EXPECT_TRUE(law->smallStrain() || law->finiteStrain()) << law->name();
  }
  EXPECT_EQ(names.size(), 6u);
}

}  // namespace
}  // namespace choc
