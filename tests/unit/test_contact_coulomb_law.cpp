// The Coulomb law of one contact node (contact/CoulombLaw.hpp): its force against the closed
// form of stick and slip, and its tangent -dF/d(delta) = scale x projector against central
// differences of the force (tests/unit/fd_tangent.hpp), in stick and in slip; a perturbed
// tangent is caught.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/CoulombLaw.hpp"
#include "fd_tangent.hpp"

namespace choc {
namespace {

const Vec3 kNormal = [] {
  const Vec3 n{0.2, -0.3, 0.9};
  const double s = norm(n);
  return Vec3{n[0] / s, n[1] / s, n[2] / s};
}();
constexpr double kKt = 2e7, kMu = 0.3, kFn = 50.0;
const Vec3 kAccepted = inPlane(Vec3{3.0, 1.0, -0.5}, kNormal);  // |F_n| ~ 3 N, inside the cone (15 N)

CoulombPoint at(const Vec3& delta) {
  CoulombPoint p = coulombTrial(kAccepted, delta, kNormal, kKt);
  coulombReturn(p, kMu, kFn);
  return p;
}

test::Residual force() {
  return [](const std::vector<double>& d) {
    const CoulombPoint p = at(Vec3{d[0], d[1], d[2]});
    return std::vector<double>{p.force[0], p.force[1], p.force[2]};
  };
}

test::Dense tangent(const Vec3& delta) {  // dF/d(delta) = -scale x projector
  const CoulombPoint p = at(delta);
  test::Dense J(3, 3);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) J(a, b) = -coulombTangentScale(p, kKt, kMu, kFn) * coulombProjector(p, kNormal, a, b);
  return J;
}

TEST(CoulombLaw, SticksInsideTheConeAndSlidesOnIt) {
  const CoulombPoint stick = at(Vec3{1e-7, 2e-7, 0});  // |F*| ~ 3 N + 4.5 N < 15 N
  EXPECT_EQ(stick.status, 1);
  const CoulombPoint slip = at(Vec3{1e-5, -2e-5, 3e-6});  // |F*| ~ 450 N > 15 N
  ASSERT_EQ(slip.status, 2);
  EXPECT_NEAR(norm(slip.force), kMu * kFn, 1e-12 * kMu * kFn);
  EXPECT_NEAR(dot(slip.force, kNormal), 0.0, 1e-12 * kMu * kFn);
  // Stick: F = P F_n - k_t P delta exactly.
  const Vec3 d = inPlane(Vec3{1e-7, 2e-7, 0}, kNormal);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(stick.force[k], kAccepted[k] - kKt * d[k], 1e-12 * kKt * 1e-7);
}

TEST(CoulombLaw, StickTangentIsTheFiniteDifferenceOfTheForce) {
  const std::vector<double> x = {1e-7, 2e-7, 0};
  test::TangentCheckOptions o;
  o.scale = 1e-7;  // the motion's size
  EXPECT_TRUE(test::tangentMatches(force(), tangent(Vec3{x[0], x[1], x[2]}), x, o));
  EXPECT_TRUE(test::tangentMismatches(force(), test::perturbed(tangent(Vec3{x[0], x[1], x[2]})), x, o));
}

TEST(CoulombLaw, SlipTangentIsTheFiniteDifferenceOfTheForce) {
  const std::vector<double> x = {1e-5, -2e-5, 3e-6};
  test::TangentCheckOptions o;
  o.scale = 1e-5;
  EXPECT_TRUE(test::tangentMatches(force(), tangent(Vec3{x[0], x[1], x[2]}), x, o));
  EXPECT_TRUE(test::tangentMismatches(force(), test::perturbed(tangent(Vec3{x[0], x[1], x[2]})), x, o));
}

}  // namespace
}  // namespace choc
