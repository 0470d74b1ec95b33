// The small-strain domain's measures (fem/ElementChecks.hpp) on motions whose strain and rotation
// are known in closed form: a rigid rotation by theta of a HEX8 (u = (R - I) X: skew H = sin theta
// about the axis, sym H = (cos theta - 1) in the plane, so ||sym H|| = sqrt(2) (1 - cos theta)), a
// uniaxial stretch (strain e, no rotation), an axisymmetric radial expansion (the hoop strain u_r /
// r), and the verdict's bounds.
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "fem/ElementChecks.hpp"

namespace choc {
namespace {

std::vector<Point3> cube() {  // the unit cube as HEX8 (Exodus order), shifted off the origin
  std::vector<Point3> X;
  for (double z : {0.0, 1.0})
    for (const auto& xy : {std::array<double, 2>{0, 0}, {1, 0}, {1, 1}, {0, 1}}) X.push_back({xy[0] + 2, xy[1] - 1, z + 3});
  return X;
}

const CheckPoints& hexCentre() {
  static const QuadratureRule none;
  return checkPoints(SolidShape::Hex8, none, false);
}

TEST(ElementChecks, RigidRotationIsAllRotation) {
  for (double theta : {1e-3, 0.1, 0.5}) {
    const double c = std::cos(theta), s = std::sin(theta);
    std::vector<double> ue;
    for (const Point3& X : cube()) {  // about z through the origin
      ue.push_back((c - 1) * X[0] - s * X[1]);
      ue.push_back(s * X[0] + (c - 1) * X[1]);
      ue.push_back(0.0);
    }
    const auto [strain, rotation] = smallStrainAtCentre(hexCentre(), cube(), ue, 3, false);
    EXPECT_NEAR(rotation, s, 1e-14) << theta;
    EXPECT_NEAR(strain, std::sqrt(2.0) * (1 - c), 1e-14) << theta;
  }
}

TEST(ElementChecks, UniaxialStretchIsAllStrain) {
  std::vector<double> ue;
  for (const Point3& X : cube()) ue.insert(ue.end(), {0.03 * X[0], 0.0, 0.0});
  const auto [strain, rotation] = smallStrainAtCentre(hexCentre(), cube(), ue, 3, false);
  EXPECT_NEAR(strain, 0.03, 1e-15);
  EXPECT_NEAR(rotation, 0.0, 1e-15);
}

TEST(ElementChecks, AxisymmetricExpansionHasItsHoopStrain) {
  static const QuadratureRule none;
  const CheckPoints& quad = checkPoints(SolidShape::Quad4, none, false);
  const std::vector<Point3> X = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  std::vector<double> ue;
  for (const Point3& x : X) ue.insert(ue.end(), {0.01 * x[0], 0.0});  // u_r = e r: e_rr = e_tt = e
  const auto [strain, rotation] = smallStrainAtCentre(quad, X, ue, 2, true);
  EXPECT_NEAR(strain, std::sqrt(2.0) * 0.01, 1e-15);
  EXPECT_NEAR(rotation, 0.0, 1e-15);
}

TEST(ElementChecks, VerdictBounds) {
  EXPECT_TRUE(smallStrainVerdict(0.049, true, 0.01, true).text.empty());
  const SmallStrainVerdict warned = smallStrainVerdict(0.02, true, 0.06, true);
  EXPECT_FALSE(warned.failed);
  EXPECT_FALSE(warned.strain);
  EXPECT_NE(warned.text.find("a rotation of 0.06 rad is past the small-strain bound (0.05)"), std::string::npos)
      << warned.text;
  const SmallStrainVerdict failed = smallStrainVerdict(0.51, true, 0.2, true);
  EXPECT_TRUE(failed.failed);
  EXPECT_TRUE(failed.strain);
  EXPECT_NE(failed.text.find("past the small-strain limit (0.5)"), std::string::npos) << failed.text;
  EXPECT_TRUE(smallStrainVerdict(0.0, false, 0.0, false).text.empty());
}

}  // namespace
}  // namespace choc
