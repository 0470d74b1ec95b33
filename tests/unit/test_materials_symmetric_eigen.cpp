// The 3 x 3 symmetric eigen-decomposition the finite-strain plasticity takes its principal axes
// from (SymmetricEigen.hpp): on matrices of known spectrum, distinct, paired, tripled, nearly
// paired, near the identity (an elastic b_e) and nearly diagonal (the series' range), the vectors
// are orthonormal to round-off and A V = V Lambda to round-off of ||A||. Jacobi's rotations are
// backward stable: each adds a few eps ||A||, and a decomposition takes at most about 15, so
// 50 eps ||A|| bounds the residual; the eigenvalues then agree with the known ones to that
// (Weyl) plus the round-off of forming A.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "materials/SymmetricEigen.hpp"

namespace choc {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A rotation from a unit quaternion.
Mat3 rotation(double w, double x, double y, double z) {
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

Mat3 withSpectrum(const Mat3& R, const double (&lambda)[3]) {
  Mat3 a{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) a[i][j] += R[i][k] * lambda[k] * R[j][k];
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) a[j][i] = a[i][j];
  return a;
}

double largest(const Mat3& a) {
  double m = 0.0;
  for (const auto& row : a)
    for (double v : row) m = std::max(m, std::abs(v));
  return m;
}

// Orthonormality and the residual; the eigenvalues against `lambda` when given.
void expectDecomposition(const Mat3& a, const double* lambda = nullptr) {
  const SymmetricEigen e = symmetricEigen(a);
  const Mat3& v = e.vectors;
  const double scale = largest(a);
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B) {
      double dot = 0.0;
      for (int i = 0; i < 3; ++i) dot += v[i][A] * v[i][B];
      EXPECT_NEAR(dot, A == B ? 1.0 : 0.0, 8 * kEps) << "vectors " << A << ", " << B;
    }
  for (int i = 0; i < 3; ++i)
    for (int A = 0; A < 3; ++A) {
      double av = 0.0;
      for (int k = 0; k < 3; ++k) av += a[i][k] * v[k][A];
      EXPECT_NEAR(av, e.values[A] * v[i][A], 50 * kEps * scale) << "residual row " << i << ", vector " << A;
    }
  if (!lambda) return;
  double got[3] = {e.values[0], e.values[1], e.values[2]}, want[3] = {lambda[0], lambda[1], lambda[2]};
  std::sort(got, got + 3), std::sort(want, want + 3);
  for (int A = 0; A < 3; ++A) EXPECT_NEAR(got[A], want[A], 60 * kEps * scale) << "eigenvalue " << A;
}

TEST(SymmetricEigen, KnownSpectraUnderRandomRotations) {
  const double spectra[][3] = {
      {0.5, 1.7, 3.2},                    // distinct
      {2.0, 2.0, 0.7},                    // a pair (axisymmetric compression's b_e)
      {1.3, 1.3, 1.3},                    // tripled
      {1.0, 1.0 + 1e-12, 2.0},            // nearly paired
      {1.0, 1.0 + 3e-9, 1.0 - 2e-9},      // near the identity (a small elastic strain)
      {1e-3, 1.0, 1e3},                   // six decades
      {0.2, 0.2 * (1 + 1e-7), 0.2 * (1 + 2e-7)}};
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (const auto& lambda : spectra)
    for (int trial = 0; trial < 200; ++trial) {
      SCOPED_TRACE(::testing::Message() << "spectrum " << lambda[0] << " " << lambda[1] << " " << lambda[2]);
      expectDecomposition(withSpectrum(rotation(g(rng), g(rng), g(rng), g(rng)), lambda), lambda);
      if (::testing::Test::HasFailure()) return;
    }
}

// Nearly diagonal: every rotation in the series' range (|a_pq| < 5e-5 |a_qq - a_pp|), at its upper
// end, where dropping the series' u^3 term would leave 1e-13 |a_qq - a_pp| in the matrix.
TEST(SymmetricEigen, NearlyDiagonalInTheSeriesRange) {
  for (double off : {4e-5, 1e-6, 1e-9, 1e-20}) {
    SCOPED_TRACE(::testing::Message() << "off-diagonal " << off);
    expectDecomposition(Mat3{{{1.0, off, -off}, {off, 2.0, 0.5 * off}, {-off, 0.5 * off, 3.0}}});
  }
}

// An equal pair of diagonal entries with an off-diagonal entry whose square underflows, beside a
// large one: the rotation of that pair must not divide 0 by 0.
TEST(SymmetricEigen, UnderflowingEntryBetweenEqualDiagonals) {
  expectDecomposition(Mat3{{{1.0, 1e-170, 0.5}, {1e-170, 1.0, 0.0}, {0.5, 0.0, 2.0}}});
  expectDecomposition(Mat3{{{1.0, -1e-170, 0.5}, {-1e-170, 1.0, 0.25}, {0.5, 0.25, 1.0}}});
}

TEST(SymmetricEigen, DiagonalAndZero) {
  const SymmetricEigen d = symmetricEigen(Mat3{{{3, 0, 0}, {0, -1, 0}, {0, 0, 2}}});
  EXPECT_EQ(d.values[0], 3.0);
  EXPECT_EQ(d.values[1], -1.0);
  EXPECT_EQ(d.values[2], 2.0);
  EXPECT_EQ(d.vectors, identity3());
  const SymmetricEigen z = symmetricEigen(Mat3{});
  EXPECT_EQ(z.values[0], 0.0);
  EXPECT_EQ(z.vectors, identity3());
}

}  // namespace
}  // namespace choc
