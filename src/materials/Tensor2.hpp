// Second-order tensors in three dimensions (3 x 3 matrices) and the few operations the
// finite-strain kinematics and the materials share.
#pragma once
#include <array>

namespace choc {

using Mat3 = std::array<std::array<double, 3>, 3>;

inline Mat3 identity3() { return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }

inline Mat3 transpose(const Mat3& a) {
  Mat3 t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = a[j][i];
  return t;
}

inline Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

// a^T a (the right Cauchy-Green tensor of a deformation gradient).
inline Mat3 transposeTimes(const Mat3& a) { return multiply(transpose(a), a); }

inline double determinant(const Mat3& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// a^-1 by cofactors, given det a != 0.
inline Mat3 inverse(const Mat3& a, double det) {
  Mat3 b{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      b[j][i] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
    }
  return b;
}

inline double trace(const Mat3& a) { return a[0][0] + a[1][1] + a[2][2]; }

inline double contract(const Mat3& a, const Mat3& b) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a[i][j] * b[i][j];
  return s;
}

}  // namespace choc
