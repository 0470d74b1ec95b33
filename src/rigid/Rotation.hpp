// Rotations of a rigid body: 3 x 3 matrices (row-major), the exponential map from a rotation
// vector theta (the axis theta/|theta|, turned by |theta|: Rodrigues' formula) and its inverse,
// and the derivative of exp(-theta^) p with respect to theta that the implicit rotation step's
// Newton needs (docs/theory/rigid-bodies.md, section 2).
#pragma once
#include <array>

#include "core/Vec3.hpp"

namespace choc {

using Matrix33 = std::array<double, 9>;  // row-major: entry (i, j) at 3 i + j

Matrix33 unitMatrix33();
Matrix33 transpose(const Matrix33& A);
Matrix33 operator*(const Matrix33& A, const Matrix33& B);
Vec3 operator*(const Matrix33& A, const Vec3& x);
// The matrix of x -> w x v (the cross product with w).
Matrix33 skew(const Vec3& w);
// exp(theta^): the rotation by |theta| about theta (Rodrigues), exact to round-off at any
// angle, its series near 0.
Matrix33 rotationFromVector(const Vec3& theta);
// The rotation vector of R, |theta| in [0, pi] (the inverse of rotationFromVector there).
Vec3 vectorFromRotation(const Matrix33& R);
// d/dtheta [exp(-theta^) p] (3 x 3): the change of a body-frame vector p under the incremental
// rotation theta, the tangent of the implicit step.
Matrix33 derivativeOfRotatedBack(const Vec3& theta, const Vec3& p);
// How far R is from a rotation: ||R^T R - I||_max.
double orthogonalityError(const Matrix33& R);
// R's nearest rotation (one polar step, R (3 I - R^T R) / 2): the drift of a product of many
// rotations removed.
Matrix33 reorthogonalized(const Matrix33& R);

// A symmetric 3 x 3 matrix's eigenvalues (ascending) and eigenvectors (the columns of V, a
// right-handed rotation), by Jacobi's rotations to round-off.
struct Eigen33 {
  Vec3 values{};
  Matrix33 vectors{};
};
Eigen33 eigenOfSymmetric33(const Matrix33& A);

}  // namespace choc
