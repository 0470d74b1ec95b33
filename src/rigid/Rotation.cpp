#include "rigid/Rotation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace choc {

namespace {

// The coefficients of Rodrigues' formula, exp(t^) = I + a t^ + b t^ t^ with a = sin(x)/x and
// b = (1 - cos x)/x^2 (x = |t|), and of the left Jacobian's third term c = (x - sin x)/x^3;
// their series below x = 1e-4, where the closed forms lose digits to cancellation.
struct RodriguesCoefficients {
  double a, b, c;
};

RodriguesCoefficients rodrigues(double x) {
  if (x < 1e-4) {
    const double x2 = x * x;
    return {1.0 - x2 / 6.0, 0.5 - x2 / 24.0, 1.0 / 6.0 - x2 / 120.0};
  }
  return {std::sin(x) / x, (1.0 - std::cos(x)) / (x * x), (x - std::sin(x)) / (x * x * x)};
}

Matrix33 combination(double i, const Matrix33& A, double a, const Matrix33& B, double b) {
  Matrix33 out{};
  for (int k = 0; k < 9; ++k) out[k] = A[k] * a + B[k] * b + (k % 4 == 0 ? i : 0.0);
  return out;
}

// The axial vector of R's skew part: (R - R^T) = 2 vee^.
Vec3 axial(const Matrix33& R) { return {0.5 * (R[7] - R[5]), 0.5 * (R[2] - R[6]), 0.5 * (R[3] - R[1])}; }

}  // namespace

Matrix33 unitMatrix33() { return {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

Matrix33 transpose(const Matrix33& A) { return {A[0], A[3], A[6], A[1], A[4], A[7], A[2], A[5], A[8]}; }

Matrix33 operator*(const Matrix33& A, const Matrix33& B) {
  Matrix33 C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
  return C;
}

Vec3 operator*(const Matrix33& A, const Vec3& x) {
  return {A[0] * x[0] + A[1] * x[1] + A[2] * x[2], A[3] * x[0] + A[4] * x[1] + A[5] * x[2],
          A[6] * x[0] + A[7] * x[1] + A[8] * x[2]};
}

Matrix33 skew(const Vec3& w) { return {0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0}; }

Matrix33 rotationFromVector(const Vec3& theta) {
  const RodriguesCoefficients r = rodrigues(norm(theta));
  const Matrix33 W = skew(theta);
  return combination(1.0, W, r.a, W * W, r.b);
}

// Below pi/2 from the skew part (sin x / x well conditioned); above, the axis from the
// symmetric part (1 - cos x) n n^T, its sign from the skew part, where sin x -> 0 near pi.
Vec3 vectorFromRotation(const Matrix33& R) {
  const double c = std::clamp(0.5 * (R[0] + R[4] + R[8] - 1.0), -1.0, 1.0);
  const Vec3 s = axial(R);  // sin(x) n
  const double sinx = norm(s);
  const double x = std::atan2(sinx, c);
  if (x < 0.5 * M_PI) {
    const double f = x < 1e-4 ? 1.0 + x * x / 6.0 : x / std::sin(x);
    return {f * s[0], f * s[1], f * s[2]};
  }
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (R[4 * i] > R[4 * k]) k = i;
  Vec3 n{};
  for (int i = 0; i < 3; ++i) n[i] = 0.5 * (R[3 * i + k] + R[3 * k + i]) - (i == k ? c : 0.0);
  const double len = norm(n);
  for (double& e : n) e /= len;
  if (dot(n, s) < 0) n = {-n[0], -n[1], -n[2]};
  return {x * n[0], x * n[1], x * n[2]};
}

// exp(-t^) p moves by exp(-t^) p^ J_l(t) dt, J_l(t) = I + b t^ + c t^ t^ the left Jacobian of
// the exponential (docs/theory/rigid-bodies.md, section 2).
Matrix33 derivativeOfRotatedBack(const Vec3& theta, const Vec3& p) {
  const RodriguesCoefficients r = rodrigues(norm(theta));
  const Matrix33 W = skew(theta);
  const Matrix33 left = combination(1.0, W, r.b, W * W, r.c);
  const Vec3 minus = {-theta[0], -theta[1], -theta[2]};
  return rotationFromVector(minus) * skew(p) * left;
}

double orthogonalityError(const Matrix33& R) {
  const Matrix33 P = transpose(R) * R;
  double e = 0.0;
  for (int k = 0; k < 9; ++k) e = std::max(e, std::abs(P[k] - (k % 4 == 0 ? 1.0 : 0.0)));
  return e;
}

Matrix33 reorthogonalized(const Matrix33& R) {
  const Matrix33 P = transpose(R) * R;
  return R * combination(1.5, P, -0.5, P, 0.0);
}

// Cyclic Jacobi: each sweep zeroes the three off-diagonal entries in turn; quadratic
// convergence, round-off in a handful of sweeps.
Eigen33 eigenOfSymmetric33(const Matrix33& A) {
  Matrix33 a = A, v = unitMatrix33();
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
    const double all = off + a[0] * a[0] + a[4] * a[4] + a[8] * a[8];
    if (off <= 1e-32 * all || off == 0.0) break;
    for (const auto& [p, q] : {std::pair<int, int>{0, 1}, {0, 2}, {1, 2}}) {
      const double apq = a[3 * p + q];
      if (apq == 0.0) continue;
      const double tau = (a[3 * q + q] - a[3 * p + p]) / (2.0 * apq);
      const double t = (tau >= 0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
      const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
      Matrix33 J = unitMatrix33();
      J[3 * p + p] = c, J[3 * q + q] = c, J[3 * p + q] = s, J[3 * q + p] = -s;
      a = transpose(J) * a * J;
      v = v * J;
    }
  }
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[4 * i] < a[4 * j]; });
  Eigen33 out;
  for (int c = 0; c < 3; ++c) {
    out.values[c] = a[4 * order[c]];
    for (int r = 0; r < 3; ++r) out.vectors[3 * r + c] = v[3 * r + order[c]];
  }
  const Vec3 e0 = {out.vectors[0], out.vectors[3], out.vectors[6]};
  const Vec3 e1 = {out.vectors[1], out.vectors[4], out.vectors[7]};
  const Vec3 e2 = {out.vectors[2], out.vectors[5], out.vectors[8]};
  if (dot(cross(e0, e1), e2) < 0)
    for (int r = 0; r < 3; ++r) out.vectors[3 * r + 2] = -out.vectors[3 * r + 2];
  return out;
}

}  // namespace choc
