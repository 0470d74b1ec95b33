// The mass properties of a rigid body (src/rigid/MassProperties.hpp) against a box's closed
// forms: mass rho a b c, centre at its middle, principal moments m (b^2 + c^2) / 12, ..., their
// axes the box's edges, whatever its attitude, its position and its elements.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "rigid/MassProperties.hpp"

namespace choc {
namespace {

constexpr double kA = 0.3, kB = 0.5, kC = 0.8, kRho = 7800.0;

// The box [0, a] x [0, b] x [0, c] in n x n x n HEX8, turned by Q and moved to `origin`.
MassPropertiesSum box(const Matrix33& Q, const Vec3& origin, int n, const Vec3& reference) {
  MassPropertiesSum sum(reference);
  const std::vector<Vec3> corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        std::vector<Vec3> x;
        for (const Vec3& c : corners) {
          const Vec3 local = {kA * (i + c[0]) / n, kB * (j + c[1]) / n, kC * (k + c[2]) / n};
          const Vec3 turned = Q * local;
          x.push_back({origin[0] + turned[0], origin[1] + turned[1], origin[2] + turned[2]});
        }
        sum.addElement(SolidShape::Hex8, Kinematics::ThreeD, x, kRho);
      }
  return sum;
}

void expectBox(const MassProperties& p, const Matrix33& Q, const Vec3& origin, double tol) {
  const double m = kRho * kA * kB * kC;
  EXPECT_NEAR(p.mass, m, tol * m);
  const Vec3 mid = Q * Vec3{kA / 2, kB / 2, kC / 2};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.centre[i], origin[i] + mid[i], tol * (1.0 + std::abs(origin[i])));
  const double Ia = m * (kB * kB + kC * kC) / 12, Ib = m * (kA * kA + kC * kC) / 12, Ic = m * (kA * kA + kB * kB) / 12;
  // ascending: c's axis (0.3, 0.5) smallest, then b's, then a's
  EXPECT_NEAR(p.moments[0], Ic, tol * Ia);
  EXPECT_NEAR(p.moments[1], Ib, tol * Ia);
  EXPECT_NEAR(p.moments[2], Ia, tol * Ia);
  // the first principal axis is the box's c edge, turned (up to its sign)
  const Vec3 edge = Q * Vec3{0, 0, 1};
  const Vec3 axis = {p.axes[0], p.axes[3], p.axes[6]};
  EXPECT_NEAR(std::abs(dot(edge, axis)), 1.0, tol);
}

TEST(MassProperties, ABoxHasItsClosedForms) {
  const Matrix33 I = unitMatrix33();
  expectBox(box(I, {0, 0, 0}, 1, {0, 0, 0}).properties(), I, {0, 0, 0}, 1e-13);
  const Matrix33 Q = rotationFromVector({0.3, 1.1, -0.6});
  expectBox(box(Q, {1.0, -2.0, 0.5}, 3, {1.0, -2.0, 0.5}).properties(), Q, {1.0, -2.0, 0.5}, 1e-13);
}

// 3.7e6 m from the origin, summed about one of its points: exact to the round-off of its nodes'
// coordinates (eps |x| over the elements' size 0.15 m, 5e-9; 20 times that allowed), where sums
// about the origin lose (|x| / size)^2 eps, 1e-1 here, and miss the moments by far.
TEST(MassProperties, ABodyFarFromTheOriginKeepsItsDigits) {
  const Matrix33 Q = rotationFromVector({0.3, 1.1, -0.6});
  const Vec3 far = {1e6, -3e6, 2e6};
  const double coordinates = 2.2e-16 * norm(far) / 0.15;
  expectBox(box(Q, far, 2, far).properties(), Q, far, 20 * coordinates);
  const MassProperties atOrigin = box(Q, far, 2, {0, 0, 0}).properties();
  const double Ic = kRho * kA * kB * kC * (kA * kA + kB * kB) / 12;
  EXPECT_GT(std::abs(atOrigin.moments[0] - Ic), 1e3 * 20 * coordinates * Ic);
}

// The sums of two halves (two ranks) give the whole body's.
TEST(MassProperties, SumsOfPartsAddUp) {
  MassPropertiesSum whole({0, 0, 0}), a({0, 0, 0}), b({0, 0, 0});
  whole.addPoint({1, 0, 0}, 2.0);
  whole.addPoint({-1, 0, 0}, 2.0);
  whole.addPoint({0, 2, 0}, 1.0);
  a.addPoint({1, 0, 0}, 2.0);
  b.addPoint({-1, 0, 0}, 2.0);
  b.addPoint({0, 2, 0}, 1.0);
  std::vector<double> s = a.sums();
  const std::vector<double> sb = b.sums();
  for (size_t i = 0; i < s.size(); ++i) s[i] += sb[i];
  MassPropertiesSum joined({0, 0, 0});
  joined.setSums(s);
  const MassProperties p = joined.properties(), q = whole.properties();
  EXPECT_DOUBLE_EQ(p.mass, 5.0);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(p.inertia[k], q.inertia[k], 1e-15);
  EXPECT_NEAR(p.centre[1], 0.4, 1e-16);
  // about the centre (0, 0.4, 0): I_zz = 4 (1 + 0.16) + 1 (1.6^2) = 7.2
  EXPECT_NEAR(p.inertia[8], 7.2, 1e-14);
}

TEST(MassProperties, ABodyWithoutMassIsRefused) {
  MassPropertiesSum empty({0, 0, 0});
  EXPECT_THROW(empty.properties(), std::invalid_argument);
}

}  // namespace
}  // namespace choc
