// Rotations of a rigid body: 3 x 3 matrices (row-major), the exponential map from a rotation
// vector theta (the axis theta/|theta|, turned by |theta|: Rodrigues' formula) and its inverse,
// and the derivative of exp(-theta^) p with respect to theta that the implicit rotation step's
// Newton needs (docs/theory/rigid-bodies.md, section 2).
#pragma once
#include <array>

#include "core/Vec3.hpp"

namespace choc {

using Mat3 = std::array<double, 9>;  // row-major: entry (i, j) at 3 i + j

Mat3 identity3();
Mat3 transpose(const Mat3& A);
Mat3 operator*(const Mat3& A, const Mat3& B);
Vec3 operator*(const Mat3& A, const Vec3& x);
// The matrix of x -> w x v (the cross product with w).
Mat3 skew(const Vec3& w);
// exp(theta^): the rotation by |theta| about theta (Rodrigues), exact to round-off at any
// angle, its series near 0.
Mat3 rotationFromVector(const Vec3& theta);
// The rotation vector of R, |theta| in [0, pi] (the inverse of rotationFromVector there).
Vec3 vectorFromRotation(const Mat3& R);
// d/dtheta [exp(-theta^) p] (3 x 3): the change of a body-frame vector p under the incremental
// rotation theta, the tangent of the implicit step.
Mat3 derivativeOfRotatedBack(const Vec3& theta, const Vec3& p);
// How far R is from a rotation: ||R^T R - I||_max.
double orthogonalityError(const Mat3& R);
// R's nearest rotation (one polar step, R (3 I - R^T R) / 2): the drift of a product of many
// rotations removed.
Mat3 reorthogonalized(const Mat3& R);

// A symmetric 3 x 3 matrix's eigenvalues (ascending) and eigenvectors (the columns of V, a
// right-handed rotation), by Jacobi's rotations to round-off.
struct SymmetricEigen3 {
  Vec3 values{};
  Mat3 vectors{};
};
SymmetricEigen3 symmetricEigen(const Mat3& A);

}  // namespace choc
