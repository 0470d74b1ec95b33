// The largest element eigenvalue over many elements without an eigenproblem per element
// (fem/ElementFrequencyBound.hpp: ElementEigenvalueMaximum and its two tests, Gershgorin's discs
// and a Cholesky factorisation of mu I - A): against matrices of known spectrum and against the
// eigenvalue of every element solved by LAPACK.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fem/ElementFrequencyBound.hpp"

using namespace choc;

namespace {

// Q diag(lambda) Q^T, column-major, Q orthonormal from Gram-Schmidt on a random matrix.
std::vector<double> withSpectrum(const std::vector<double>& lambda, std::mt19937& rng) {
  const int n = static_cast<int>(lambda.size());
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> Q(size_t(n) * n);
  for (int j = 0; j < n; ++j) {
    double* q = Q.data() + size_t(j) * n;
    for (int pass = 0; pass < 2; ++pass) {  // twice: orthogonal to round-off
      if (pass == 0)
        for (int i = 0; i < n; ++i) q[i] = g(rng);
      for (int k = 0; k < j; ++k) {
        const double* p = Q.data() + size_t(k) * n;
        double d = 0.0;
        for (int i = 0; i < n; ++i) d += p[i] * q[i];
        for (int i = 0; i < n; ++i) q[i] -= d * p[i];
      }
      double norm = 0.0;
      for (int i = 0; i < n; ++i) norm += q[i] * q[i];
      for (int i = 0; i < n; ++i) q[i] /= std::sqrt(norm);
    }
  }
  std::vector<double> A(size_t(n) * n, 0.0);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int k = 0; k < n; ++k) A[size_t(b) * n + a] += Q[size_t(k) * n + a] * lambda[size_t(k)] * Q[size_t(k) * n + b];
  return A;
}

// A spectrum of n values with the largest 1: a cluster just below it, the rest spread down to
// `lowest` (negative: an indefinite tangent).
std::vector<double> spectrum(int n, double lowest, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> lambda{1.0, 1.0 - 1e-6, 1.0 - 1e-3};
  while (int(lambda.size()) < n) lambda.push_back(lowest + (1.0 - lowest) * u(rng));
  return lambda;
}

TEST(ElementEigenvalueMaximum, CholeskySeparatesTheLargestEigenvalue) {
  std::mt19937 rng(11);
  std::vector<double> R;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 4 + trial % 27;
    const double lowest = trial % 2 ? 0.0 : -10.0;
    const std::vector<double> A = withSpectrum(spectrum(n, lowest, rng), rng);
    SCOPED_TRACE("n = " + std::to_string(n) + ", lowest " + std::to_string(lowest));
    // A holds its spectrum to about n eps max|lambda| (1e-13 here): margins of 1e-9 decide.
    double bound = 0.0;
    EXPECT_TRUE(choleskyBelow(A.data(), n, 1.0 + 1e-9, R, bound));
    EXPECT_GE(bound, 1.0 + 1e-9);
    EXPECT_LE(bound, 1.0 + 1e-9 + 1e-12 * (1.0 - lowest));  // (n + 1) eps tr: small
    EXPECT_FALSE(choleskyBelow(A.data(), n, 1.0 - 1e-9, R, bound));
    EXPECT_FALSE(choleskyBelow(A.data(), n, 0.5, R, bound));
  }
}

TEST(ElementEigenvalueMaximum, GershgorinBoundsTheLargestEigenvalue) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 4 + trial % 27;
    const std::vector<double> A = withSpectrum(spectrum(n, -2.0, rng), rng);
    double bound = 0.0;
    EXPECT_FALSE(gershgorinBelow(A.data(), n, 1.0 - 1e-9, bound));
    EXPECT_GE(bound, 1.0 - 1e-12);
    // exactly at its own bound it answers yes
    EXPECT_TRUE(gershgorinBelow(A.data(), n, bound, bound));
  }
  // Symmetric circulants of positive entries: the vector of ones is the Perron vector, and the
  // largest eigenvalue is the row sum, where Gershgorin's bound is sharp.
  for (int n : {5, 12, 24}) {
    std::uniform_real_distribution<double> u(0.1, 1.0);
    std::vector<double> c(size_t(n / 2 + 1));
    for (double& x : c) x = u(rng);
    std::vector<double> A(size_t(n) * n);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const int d = std::min(i, n - i);
      sum += c[size_t(d)];
      for (int j = 0; j < n; ++j) A[size_t(j) * n + (i + j) % n] = c[size_t(d)];
    }
    double bound = 0.0;
    EXPECT_FALSE(gershgorinBelow(A.data(), n, sum * (1 - 1e-12), bound));
    EXPECT_GE(bound, sum);
    EXPECT_LE(bound, sum * (1 + 1e-13));
  }
  // A diagonal matrix: the discs are its entries, the bound the largest to round-off.
  const std::vector<double> D{2.0, 0.0, 0.0, 0.0, -5.0, 0.0, 0.0, 0.0, 3.0};
  double bound = 0.0;
  EXPECT_TRUE(gershgorinBelow(D.data(), 3, 3.0 * (1 + 1e-14), bound));
  EXPECT_NEAR(bound, 3.0, 1e-14);
  EXPECT_FALSE(gershgorinBelow(D.data(), 3, 3.0 * (1 - 1e-14), bound));
}

struct Element {
  DenseMatrix K, M;
  std::vector<double> mass;
};

// A stiffness of rank `rank` < n (rigid-body modes, as elements have), positive semi-definite
// times `scale`, and a random lumped mass.
Element randomElement(int n, int rank, double scale, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  Element e{DenseMatrix(n, n), DenseMatrix(n, n), std::vector<double>(size_t(n))};
  for (int r = 0; r < rank; ++r) {
    std::vector<double> b(static_cast<size_t>(n));
    for (double& x : b) x = g(rng);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) e.K(i, j) += scale * b[size_t(i)] * b[size_t(j)];
  }
  for (int i = 0; i < n; ++i) e.M(i, i) = e.mass[size_t(i)] = u(rng);
  return e;
}

TEST(ElementEigenvalueMaximum, EqualsTheLargestSolvedEigenvalue) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.2, 1.0);
  for (bool increasing : {false, true}) {
    std::vector<Element> elements;
    std::vector<double> scales;
    for (int e = 0; e < 60; ++e) scales.push_back(u(rng));
    if (increasing) std::sort(scales.begin(), scales.end());
    std::vector<char> active(24, 1);
    active[3] = active[17] = 0;  // fixed rows are left out, as elementEigenvalue leaves them
    ElementEigenvalueMaximum maximum;
    double largest = 0.0;
    for (double s : scales) {
      const Element el = randomElement(24, 18, s, rng);
      largest = std::max(largest, elementEigenvalue(el.K, el.M, active));
      maximum.add(el.K, el.mass, active);
    }
    SCOPED_TRACE(increasing ? "increasing" : "random order");
    EXPECT_EQ(maximum.elements(), 60);
    EXPECT_GE(maximum.value(), largest * (1 - 1e-14));
    EXPECT_LE(maximum.value(), largest * (1 + 2e-10));
    if (!increasing) {
      // records of a random sequence: about ln 60 = 4 of them are solved
      EXPECT_LT(maximum.solved(), 20);
    }
  }
}

TEST(ElementEigenvalueMaximum, SolvesOneOfNearlyEqualElements) {
  // 50 copies of an element, each stiffer than the one before by 1e-12 (an undeformed mesh, its
  // elements equal to round-off): the first is solved, the others pass within the tie margin,
  // and the value still bounds the last, the largest.
  std::mt19937 rng(14);
  Element el = randomElement(24, 18, 1.0, rng);
  const std::vector<char> active(24, 1);
  ElementEigenvalueMaximum maximum;
  double lambda = 0.0;
  for (int e = 0; e < 50; ++e) {
    DenseMatrix K = el.K;
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j) K(i, j) *= 1.0 + 1e-12 * e;
    maximum.add(K, el.mass, active);
    lambda = std::max(lambda, elementEigenvalue(K, el.M, active));
  }
  EXPECT_EQ(maximum.solved(), 1);
  EXPECT_GE(maximum.value(), lambda * (1 - 1e-14));
  EXPECT_LE(maximum.value(), lambda * (1 + 2e-10));
}

TEST(ElementEigenvalueMaximum, AMasslessStiffRowMakesItInfinite) {
  std::mt19937 rng(15);
  Element a = randomElement(24, 18, 1.0, rng), b = randomElement(24, 18, 1.0, rng);
  const std::vector<char> active(24, 1);
  b.mass[7] = 0.0;
  ElementEigenvalueMaximum maximum;
  maximum.add(a.K, a.mass, active);
  maximum.add(b.K, b.mass, active);
  maximum.add(a.K, a.mass, active);
  EXPECT_TRUE(std::isinf(maximum.value()));
  // and an element without stiffness adds nothing
  ElementEigenvalueMaximum none;
  none.add(DenseMatrix(24, 24), a.mass, active);
  EXPECT_EQ(none.value(), 0.0);
}

}  // namespace
