// The element eigenvalue bound of the critical step (Irons and Treharne 1971): for K = sum_e K_e
// and a lumped M = sum_e M_e, both on the unknowns, every eigenvalue of K x = lambda M x lies
// below the largest element eigenvalue max_e lambda_max(K_e, M_e), each element restricted to
// its unknown DOFs (a Rayleigh quotient of sums is at most the largest quotient of its terms).
// On a uniform bar of 2-node elements it gives 4 c^2 / h^2, the exact highest eigenvalue of a
// free chain (dt = h / c); in 3D it is far tighter than Gershgorin's row sums, which add the
// off-diagonal couplings of every element meeting at a node.
#pragma once
#include <algorithm>
#include <limits>
#include <vector>

#include "fem/DenseMatrix.hpp"

namespace choc {

// lambda_max(K, M) on the rows and columns flagged in `active`, M diagonal there. Returns +inf
// when M has an off-diagonal entry on them, or a diagonal entry that is not positive where K's
// row is not zero (the bound does not apply); 0 when no active row carries stiffness.
double elementEigenvalue(const DenseMatrix& K, const DenseMatrix& M, const std::vector<char>& active);

// Whether mu I - A has a Cholesky factor in floating point (A symmetric n x n, column-major, its
// upper triangle read; R is the work space). When it has, every eigenvalue of A is at most `bound`
// = mu + (n + 1) eps tr(mu I - A): the computed factor is exact for mu I - A + E with
// |E| <= gamma_(n+1) |R^T| |R| (Higham, Accuracy and Stability, thm 10.3), whose 2-norm is at most
// gamma_(n+1) tr(R^T R), about gamma_(n+1) tr(mu I - A).
bool choleskyBelow(const double* A, int n, double mu, std::vector<double>& R, double& bound);

// Whether Gershgorin's discs of A (as above) lie at or below mu: `bound` is the largest disc's
// right end, raised by its sum's rounding. About a quarter of choleskyBelow's cost, and enough for
// an element well below the largest.
bool gershgorinBelow(const double* A, int n, double mu, double& bound);

// max_e lambda_max(K_e, M_e) over many elements (the deformed mesh's bound, estimated again during
// a run) without an eigenproblem per element. Each element is tested against the largest
// eigenvalue so far, raised by a relative 1e-10 so that equal elements pass: first by Gershgorin's
// discs, then by one Cholesky factorisation (n^3 / 6 products, against DSYEV's reduction to
// tridiagonal form, 2 n^3 / 3, and its QR iterations). Only an element that fails both is solved:
// about 1 in 50 on the Taylor bar. value() is at least every element's lambda_max (DSYEV's, or the
// tests' bound) and exceeds the largest by at most that 1e-10 and round-off. For one order of the
// elements it is a function of them, so a run and its restart repeat bit for bit; another
// partition may move it within the margin, which changes a sub-step count only for a step within
// 1e-10 of a multiple of the stable step.
class ElementEigenvalueMaximum {
 public:
  // One element: its tangent K and lumped (diagonal) mass on its rows, `active` its unknown rows.
  void add(const DenseMatrix& K, const std::vector<double>& mass, const std::vector<char>& active);
  double value() const { return std::max(largest_, below_); }
  long long elements() const { return elements_; }
  long long solved() const { return solved_; }  // elements whose eigenproblem was solved

 private:
  static constexpr double kTieMargin = 1e-10;
  double largest_ = 0.0, below_ = 0.0;
  long long elements_ = 0, solved_ = 0;
  std::vector<int> keep_;
  std::vector<double> scale_, A_, R_;
};

}  // namespace choc
