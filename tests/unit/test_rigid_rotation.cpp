// The rotation library of the rigid bodies (src/rigid/Rotation.hpp): the exponential map and its
// inverse at every angle, the derivative the implicit rotation step uses (against central
// differences), the re-orthogonalisation and the symmetric eigen-decomposition of an inertia
// tensor.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "rigid/Rotation.hpp"

namespace choc {
namespace {

Vec3 along(const Vec3& axis, double angle) {
  const double n = norm(axis);
  return {axis[0] / n * angle, axis[1] / n * angle, axis[2] / n * angle};
}

double maxDifference(const Matrix33& A, const Matrix33& B) {
  double e = 0.0;
  for (int k = 0; k < 9; ++k) e = std::max(e, std::abs(A[k] - B[k]));
  return e;
}

// exp then log gives the vector back, and exp is a rotation to a few ulps, from 1e-9 rad to within 1e-7 of
// pi (where the axis comes from the symmetric part): round-off relative to the angle, 1e-15
// near 0, and near pi the axis's error eps / (pi - x) amplified by the angle.
TEST(Rotation, TheVectorOfTheExponentialIsTheVectorItself) {
  const Vec3 axis = {0.3, -0.5, 0.8};
  for (double angle : {1e-9, 1e-5, 2e-4, 0.3, 1.5, 1.6, 2.5, 3.0, M_PI - 1e-4, M_PI - 1e-7}) {
    const Vec3 t = along(axis, angle);
    const Matrix33 R = rotationFromVector(t);
    EXPECT_LT(orthogonalityError(R), 2e-15) << angle;  // a few ulps: R's entries to 2 eps, summed by three
    const Vec3 back = vectorFromRotation(R);
    const double allowed = angle > 3.0 ? 1e-15 / (M_PI - angle) + 1e-14 : 1e-14 * angle + 1e-300;
    EXPECT_LE(norm(back - t), allowed) << "angle " << angle;
  }
}

// Rodrigues' formula against the rotation about z written out.
TEST(Rotation, TheExponentialTurnsAboutItsAxis) {
  const double a = 0.7;
  const Matrix33 Rz = {std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
  EXPECT_LT(maxDifference(rotationFromVector({0, 0, a}), Rz), 1e-16);
  const Vec3 v = rotationFromVector({0, 0, a}) * Vec3{1, 0, 0};
  EXPECT_NEAR(v[0], std::cos(a), 1e-16);
  EXPECT_NEAR(v[1], std::sin(a), 1e-16);
}

// d/dtheta [exp(-theta^) p] against central differences (docs/theory/rigid-bodies.md,
// section 2), at a small and a large angle and at theta = 0 (the series), and a perturbed
// derivative caught.
TEST(Rotation, TheDerivativeOfTheRotatedBackVectorIsItsCentralDifferences) {
  const Vec3 p = {0.4, 1.3, -0.7};
  for (const Vec3& theta : {Vec3{0, 0, 0}, Vec3{1e-6, -2e-6, 3e-6}, Vec3{0.2, -0.4, 0.1}, Vec3{1.1, 0.9, -1.7}}) {
    const test::Residual R = [&](const std::vector<double>& x) {
      const Vec3 r = rotationFromVector({-x[0], -x[1], -x[2]}) * p;
      return std::vector<double>{r[0], r[1], r[2]};
    };
    const Matrix33 D = derivativeOfRotatedBack(theta, p);
    test::Dense J(3, 3);
    for (int k = 0; k < 9; ++k) J.a[size_t(k)] = D[size_t(k)];
    const std::vector<double> x = {theta[0], theta[1], theta[2]};
    test::TangentCheckOptions o;
    o.scale = 1.0;  // radians: the length over which the rotation varies
    EXPECT_TRUE(test::tangentMatches(R, J, x, o)) << "theta " << norm(theta);
    EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), x, o));
  }
}

// One polar step brings a product of many rotations back to a rotation without moving it.
TEST(Rotation, ReorthogonalisationRemovesTheDriftOnly) {
  Matrix33 R = unitMatrix33();
  const Matrix33 step = rotationFromVector({0.013, -0.021, 0.007});
  for (int i = 0; i < 100000; ++i) R = R * step;
  const double drift = orthogonalityError(R);
  const Matrix33 Q = reorthogonalized(R);
  EXPECT_LT(orthogonalityError(Q), 2e-15);
  EXPECT_LE(maxDifference(Q, R), 2 * drift + 1e-16);
}

// An inertia tensor with known principal axes (a rotation of diag(2, 3, 5)): the moments
// ascending, the axes to round-off, a right-handed frame.
TEST(Rotation, TheEigenDecompositionGivesThePrincipalFrame) {
  const Matrix33 Q = rotationFromVector({0.5, -1.2, 0.8});
  const Matrix33 D = {2, 0, 0, 0, 3, 0, 0, 0, 5};
  const Matrix33 A = Q * D * transpose(Q);
  const Eigen33 e = eigenOfSymmetric33(A);
  EXPECT_NEAR(e.values[0], 2, 1e-14);
  EXPECT_NEAR(e.values[1], 3, 1e-14);
  EXPECT_NEAR(e.values[2], 5, 1e-14);
  EXPECT_LT(orthogonalityError(e.vectors), 1e-15);
  const Matrix33 back = e.vectors * D * transpose(e.vectors);
  EXPECT_LT(maxDifference(back, A), 1e-14);
  const Vec3 c0 = {e.vectors[0], e.vectors[3], e.vectors[6]}, c1 = {e.vectors[1], e.vectors[4], e.vectors[7]},
             c2 = {e.vectors[2], e.vectors[5], e.vectors[8]};
  EXPECT_NEAR(dot(cross(c0, c1), c2), 1.0, 1e-15);
  // A repeated moment (a cylinder's): any orthonormal frame of the plane, still exact.
  const Matrix33 A2 = Q * Matrix33{2, 0, 0, 0, 2, 0, 0, 0, 5} * transpose(Q);
  const Eigen33 e2 = eigenOfSymmetric33(A2);
  EXPECT_LT(maxDifference(e2.vectors * Matrix33{2, 0, 0, 0, 2, 0, 0, 0, 5} * transpose(e2.vectors), A2), 1e-14);
}

}  // namespace
}  // namespace choc
