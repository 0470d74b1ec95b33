// The logarithm and the exponential of a symmetric 3 x 3 matrix near a multiple of the identity,
// by series and without its principal axes: the elastic left Cauchy-Green tensor b_e of a metal
// (elastic strains of 1e-3 to 1e-2) in the explicit plastic update, where the axes (cyclic
// Jacobi rotations, SymmetricEigen.hpp) cost most of a point's update. Same results to
// round-off; the implicit tangent, which needs the axes, keeps them.
//
// For any s > 0, log b = ln(s) I + log(b / s); with s = tr(b) / 3 (no cube root) b / s is near I,
// and the deviator of log b, log bbar (bbar = b / det(b)^(1/3)), is that of log(b / s):
//   log(b / s) = 2 artanh z = 2 (z + z^3 / 3 + z^5 / 5 + ...),   z = (b - s I)(b + s I)^-1,
// z symmetric (b - s I and (b + s I)^-1 commute) with eigenvalues tanh(l_A / 2), l_A those of
// log(b / s), so ||z|| is about half the logarithmic strain's deviator; the series stops when a
// term is below 1e-17 of ||z|| (||z|| = 0.005: four terms), and is used only for ||z||_F <= 0.25
// (at most 14 terms). exp x = I + x + x^2 / 2! + ... likewise, for ||x||_F <= 1. The powers of
// one symmetric matrix commute, so their products are symmetric: six entries each (Sym3).
#pragma once
#include <cmath>

#include "materials/Tensor2.hpp"

namespace choc {

namespace nearscalar {

// A symmetric 3 x 3 matrix: xx, yy, zz, xy, yz, zx.
struct Sym3 {
  double v[6];
};

inline Sym3 upper(const Mat3& a) { return {{a[0][0], a[1][1], a[2][2], a[0][1], a[1][2], a[0][2]}}; }

inline Mat3 full(const Sym3& s) {
  const double* v = s.v;
  return {{{v[0], v[3], v[5]}, {v[3], v[1], v[4]}, {v[5], v[4], v[2]}}};
}

// a b for a and b that commute (their product is symmetric).
inline Sym3 product(const Sym3& a, const Sym3& b) {
  const double *x = a.v, *y = b.v;
  return {{x[0] * y[0] + x[3] * y[3] + x[5] * y[5], x[3] * y[3] + x[1] * y[1] + x[4] * y[4],
           x[5] * y[5] + x[4] * y[4] + x[2] * y[2], x[0] * y[3] + x[3] * y[1] + x[5] * y[4],
           x[3] * y[5] + x[1] * y[4] + x[4] * y[2], x[0] * y[5] + x[3] * y[4] + x[5] * y[2]}};
}

inline double squaredNorm(const Sym3& a) {
  const double* v = a.v;
  return v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + 2 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
}

// a^-1 of a symmetric positive definite a (its cofactors over det a).
inline Sym3 inverse(const Sym3& a) {
  const double* v = a.v;
  const double c0 = v[1] * v[2] - v[4] * v[4], c1 = v[0] * v[2] - v[5] * v[5], c2 = v[0] * v[1] - v[3] * v[3];
  const double c3 = v[4] * v[5] - v[3] * v[2], c4 = v[3] * v[5] - v[0] * v[4], c5 = v[3] * v[4] - v[1] * v[5];
  const double r = 1.0 / (v[0] * c0 + v[3] * c3 + v[5] * c5);
  return {{r * c0, r * c1, r * c2, r * c3, r * c4, r * c5}};
}

}  // namespace nearscalar

// log b of a symmetric positive definite b near a multiple of I: false (nothing written) when
// det b <= 0 or ||z||_F > 0.25 (far from one: the caller takes the principal axes). Else
// logBar = log bbar (the deviator of log b) and lnDet = ln det b.
inline bool logNearScalar(const Mat3& b, Mat3& logBar, double& lnDet) {
  using namespace nearscalar;
  const double det = determinant(b);
  if (!(det > 0) || !std::isfinite(det)) return false;
  const double s = trace(b) / 3;
  Sym3 minus = upper(b), plus = upper(b);
  for (int i = 0; i < 3; ++i) minus.v[i] -= s, plus.v[i] += s;
  const Sym3 z = product(minus, inverse(plus));
  const double size2 = squaredNorm(z);
  if (!(size2 <= 0.25 * 0.25)) return false;
  const Sym3 z2 = product(z, z);
  Sym3 sum = z, power = z;
  for (int k = 1; k < 40 && size2 > 0; ++k) {
    power = product(power, z2);
    const double w = 1.0 / (2 * k + 1);
    for (int i = 0; i < 6; ++i) sum.v[i] += w * power.v[i];
    if (w * w * squaredNorm(power) <= 1e-34 * size2) break;
  }
  const double dev = 2 * (sum.v[0] + sum.v[1] + sum.v[2]) / 3;  // tr log(b / s) / 3
  for (int i = 0; i < 6; ++i) sum.v[i] *= 2;
  for (int i = 0; i < 3; ++i) sum.v[i] -= dev;
  logBar = full(sum);
  lnDet = std::log(det);
  return true;
}

// exp x of a symmetric x with ||x||_F <= 1 (the caller's bound), by its Taylor series until a
// term is below 1e-17.
inline Mat3 expSmall(const Mat3& x) {
  using namespace nearscalar;
  const Sym3 a = upper(x);
  Sym3 sum = {{1, 1, 1, 0, 0, 0}}, term = sum;
  for (int k = 1; k < 40; ++k) {
    term = product(term, a);
    const double w = 1.0 / k;
    for (int i = 0; i < 6; ++i) {
      term.v[i] *= w;
      sum.v[i] += term.v[i];
    }
    if (squaredNorm(term) <= 1e-34) break;
  }
  return full(sum);
}

}  // namespace choc
