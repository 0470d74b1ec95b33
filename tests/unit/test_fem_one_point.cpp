// The one-point HEX8 (3D) and QUAD4 (plane strain) with hourglass stiffness
// (FiniteStrainSolid.hpp): its tangent against central differences of its force (hyperelastic,
// and J2 from a yielded state), its force the derivative of its energy, a homogeneous deformation
// giving the fully integrated element's force, no force under rigid rotations, each hourglass
// mode stiff with the energy the header's scaling gives a cube, and the refusals.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "materials/HyperelasticPoint.hpp"
#include "materials/J2Point.hpp"
#include "finite_strain_states.hpp"
#include "test_fem_solid_cases.hpp"

namespace choc {
namespace {

using test::ElementCase;

constexpr double kE = 1.0e3, kNu = 0.3, kQ = 0.05;

std::vector<ElementCase> onePointCases() {
  std::vector<ElementCase> cases;
  for (const ElementCase& c : test::allElementCases())
    if ((c.topology == "HEX8" && c.kinematics == Kinematics::ThreeD) ||
        (c.topology == "QUAD4" && c.kinematics == Kinematics::PlaneStrain))
      cases.push_back(c);
  return cases;
}

FiniteStrainSolid onePoint(const ElementCase& c, std::shared_ptr<const MaterialPoint> m, double Q = kQ) {
  return FiniteStrainSolid(c.topology, c.kinematics, std::move(m), ElementFormulation{false, true, Q});
}

std::shared_ptr<const MaterialPoint> neoHookean() { return hyperelasticPoint(makeHyperelastic("neo-Hookean", kE, kNu)); }

// A general deformation plus a nodal pattern: not homogeneous, so the hourglass modes are loaded.
std::vector<double> wobbled(const ElementCase& c, double wobble) {
  std::vector<double> u = test::displacementOf(c, test::generalGradient(c.kinematics));
  for (size_t j = 0; j < u.size(); ++j) u[j] += wobble * std::sin(1.7 * double(j) + 0.3);
  return u;
}

class OnePoint : public ::testing::TestWithParam<ElementCase> {};

TEST_P(OnePoint, TangentMatchesCentralDifferencesOfTheForce) {
  const ElementCase& c = GetParam();
  const FiniteStrainSolid el = onePoint(c, neoHookean());
  test::expectTangentMatchesTheForce(el, el.geometry(c.x), wobbled(c, 0.02));
}

TEST_P(OnePoint, PlasticTangentMatchesCentralDifferencesOfTheForce) {
  const ElementCase& c = GetParam();
  for (bool finite : {false, true}) {
    const auto m = std::make_shared<const J2Plasticity>(linearHardening(kE, kNu, kE / 200, kE / 20), finite);
    const double asymmetry = test::checkPlasticTangent(onePoint(c, j2Point(m)), c, 0.004, finite ? "finite" : "small");
    EXPECT_LE(asymmetry, 1e-12);  // one material point and a symmetric hourglass stiffness
  }
}

// The force is the derivative of the energy evaluate returns (the material's V W(F) plus the
// hourglass energy): the balance counts what the force does.
TEST_P(OnePoint, ForceIsTheDerivativeOfTheElementEnergy) {
  const ElementCase& c = GetParam();
  test::expectForceIsTheEnergysDerivative(onePoint(c, neoHookean()), c, wobbled(c, 0.02));
}

// Under a homogeneous deformation the mean gradient is exact and every hourglass amplitude is
// zero: the fully integrated element's force and energy, on distorted elements too.
TEST_P(OnePoint, HomogeneousDeformationIsTheFullyIntegratedElements) {
  const ElementCase& c = GetParam();
  const std::vector<double> u = test::displacementOf(c, test::generalGradient(c.kinematics));
  std::vector<double> f, fs;
  const double w = onePoint(c, neoHookean()).evaluate(c.x, u, f, nullptr);
  const double ws = FiniteStrainSolid(c.topology, c.kinematics, neoHookean(), ElementFormulation{}).evaluate(c.x, u, fs, nullptr);
  double scale = 0.0;
  for (double v : fs) scale = std::max(scale, std::abs(v));
  for (size_t k = 0; k < f.size(); ++k) EXPECT_NEAR(f[k], fs[k], 1e-12 * scale);
  EXPECT_NEAR(w, ws, 1e-12 * std::abs(ws));
}

// A rigid rotation is a linear field: no stress and no hourglass amplitude, whatever the angle.
TEST_P(OnePoint, RigidRotationsCreateNoForce) {
  const ElementCase& c = GetParam();
  const FiniteStrainSolid el = onePoint(c, neoHookean());
  for (double degrees : {90.0, 180.0}) {
    const std::vector<double> u =
        test::displacementOf(c, test::rotation(c.kinematics, degrees * std::acos(-1.0) / 180), {0.3, -0.2, 0.4});
    std::vector<double> f;
    const double w = el.evaluate(c.x, u, f, nullptr);
    for (double v : f) EXPECT_NEAR(v, 0.0, 1e-12 * kE) << degrees << " degrees";
    EXPECT_NEAR(w, 0.0, 1e-12 * kE);
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, OnePoint, ::testing::ValuesIn(onePointCases()),
                         [](const auto& info) { return info.param.label; });

// Every hourglass pattern of every component is stiff (one point alone leaves them free), and on a
// cube of side h the xi-eta mode u_x = a xi eta has the energy Q (2/3) (lambda + 2 mu) a^2 h, the
// normal-stress part of the fully integrated cube's (a square: the same without h, per unit
// thickness), the scaling the header states.
TEST(OnePointHourglass, EveryModeIsStiffWithTheCubesEnergy) {
  const double h = 0.7, a = 1e-3, modulus = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
  for (bool threeD : {true, false}) {
    ElementCase c;
    c.topology = threeD ? "HEX8" : "QUAD4";
    c.kinematics = threeD ? Kinematics::ThreeD : Kinematics::PlaneStrain;
    const auto& xi = nodeNaturalCoordinates(solidTopology(c.topology));
    for (const Point3& p : xi) c.x.push_back({0.2 + h / 2 * p[0], -0.1 + h / 2 * p[1], threeD ? h / 2 * p[2] : 0.0});
    const FiniteStrainSolid el = onePoint(c, neoHookean());
    const ElementGeometry g = el.geometry(c.x);
    const int nc = threeD ? 3 : 2, n = int(xi.size());
    std::vector<double> f, u(size_t(n * nc));
    for (int a1 = 0; a1 < n; ++a1) u[size_t(a1 * nc)] = a * xi[size_t(a1)][0] * xi[size_t(a1)][1];
    EXPECT_NEAR(el.evaluate(g, u, f, nullptr), kQ * 2.0 / 3 * modulus * a * a * (threeD ? h : 1.0),
                1e-6 * kQ * modulus * a * a);  // the material's part is O(a^4)
    DenseMatrix K;
    el.evaluate(g, std::vector<double>(u.size(), 0.0), f, &K);
    const int modes = threeD ? 4 : 1;
    for (int m = 0; m < modes; ++m)
      for (int i = 0; i < nc; ++i) {
        std::vector<double> v(u.size(), 0.0);
        for (int b = 0; b < n; ++b) {
          const Point3& p = xi[size_t(b)];
          v[size_t(b * nc + i)] = m == 0 ? p[1] * p[2] : m == 1 ? p[2] * p[0] : m == 2 ? p[0] * p[1] : p[0] * p[1] * p[2];
          if (!threeD) v[size_t(b * nc + i)] = p[0] * p[1];
        }
        double vKv = 0.0;
        for (size_t r = 0; r < v.size(); ++r)
          for (size_t s = 0; s < v.size(); ++s) vKv += v[r] * K(int(r), int(s)) * v[s];
        EXPECT_NEAR(vKv, g.hourglassStiffness * n * n, 1e-10 * vKv) << "mode " << m << " component " << i;
      }
  }
}

TEST(OnePointRefused, OnOtherElementsAndOutOfRange) {
  const auto m = neoHookean();
  const ElementFormulation one{false, true, kQ};
  EXPECT_THROW(FiniteStrainSolid("TET4", Kinematics::ThreeD, m, one), std::invalid_argument);
  EXPECT_THROW(FiniteStrainSolid("HEX20", Kinematics::ThreeD, m, one), std::invalid_argument);
  EXPECT_THROW(FiniteStrainSolid("QUAD4", Kinematics::Axisymmetric, m, one), std::invalid_argument);
  EXPECT_THROW(FiniteStrainSolid("HEX8", Kinematics::ThreeD, m, ElementFormulation{false, true, 0.0}),
               std::invalid_argument);
  EXPECT_THROW(FiniteStrainSolid("HEX8", Kinematics::ThreeD, m, ElementFormulation{true, true, kQ}),
               std::invalid_argument);
  EXPECT_NO_THROW(FiniteStrainSolid("QUAD4", Kinematics::PlaneStrain, m, one));
}

}  // namespace
}  // namespace choc
