// Finite-difference check of a tangent: for a residual R(x) (x in R^n, R in R^m, as
// std::vector<double>) and its analytic tangent J = dR/dx at x (a dense m x n matrix, e.g.
// the assembled CRS matrix of a small unit-test system made dense by denseOf), the central
// differences
//
//     J_fd(:, j) = (R(x + h_j e_j) - R(x - h_j e_j)) / (2 h_j),
//     h_j = eps^(1/3) max(|x_j|, s_j)                                                  (1)
//
// (eps = 2.2e-16 the machine epsilon, s_j the scale of component j: the size x_j has in the
// problem when it happens to be zero) are compared with J by the relative error
//
//     e = ||J - J_fd||_F / ||J||_F.
//
// Tolerance. The central difference of entry (i, j) errs by
//
//     |J_fd,ij - J_ij| <= h_j^2 / 6 |d^3 R_i / dx_j^3|  +  eps |R_i| / h_j              (2)
//
// (truncation + the round-off of the two evaluations, |R_i| the size of the terms R_i sums).
// With h_j of (1) both terms are eps^(2/3) ~ 3.7e-11 times (s_j^2 |R'''| / 6 + |R| / s_j),
// which is O(|J|) when s_j is the length over which R varies: the expected relative error is
// ~1e-10. The default tolerance, tau = 1e-6, leaves four decades for residuals varying on a
// shorter scale than s, and is still far below the 1e-3 ||J|| of a perturbed entry or any
// dropped term larger than 1e-6 ||J||. The check also ESTIMATES (2) at the state, per entry:
//
//     E_ij = |J_fd,ij(2h) - J_fd,ij(h)|  +  eps max(|R_i(x +- h e_j)|, residualScale) / h_j,
//
// the first term 3 times the O(h^2) truncation of a smooth residual, and of the size of an
// O(h) error where the residual's derivative jumps within the step (a kink: stick-slip,
// open-closed, or the slivers a clipped mortar overlap gains), the second the round-off of
// the two evaluations where they differ (residualScale: the size of the terms R sums when
// they cancel, e.g. the positions a gap is computed from). It fails when ||E||_F / ||J||_F
// exceeds tau: the finite differences are then no reference, and the test must move its
// state or its step scale, not widen its tolerance.
//
// Each tangent test asserts both: the real tangent passes (tangentMatches), and a
// deliberately perturbed one fails (tangentMismatches with perturbed(J) or withoutEntries).
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/TpetraTypes.hpp"

namespace choc::test {

// A dense row-major matrix.
struct Dense {
  int rows = 0, cols = 0;
  std::vector<double> a;
  Dense() = default;
  Dense(int m, int n) : rows(m), cols(n), a(size_t(m) * size_t(n), 0.0) {}
  double& operator()(int i, int j) { return a[size_t(i) * cols + j]; }
  double operator()(int i, int j) const { return a[size_t(i) * cols + j]; }
  double frobenius() const {
    double s = 0.0;
    for (double v : a) s += v * v;
    return std::sqrt(s);
  }
};

using Residual = std::function<std::vector<double>(const std::vector<double>&)>;

struct TangentCheckOptions {
  double tolerance = 1e-6;    // tau, on ||J - J_fd||_F / ||J||_F
  double scale = 1.0;         // s_j of (1) for every component, unless `scales` is given
  std::vector<double> scales;  // s_j per component (size n), overrides `scale`
  double residualScale = 0.0;  // size of the terms R sums, for the round-off estimate
};

struct TangentCheck {
  bool passed = false;
  double relativeError = 0.0;  // ||J - J_fd||_F / ||J||_F
  double fdError = 0.0;        // the estimated error of J_fd, relative to ||J||_F
  double tolerance = 0.0;
  double norm = 0.0;           // ||J||_F
  int worstRow = -1, worstCol = -1;
  double worstAnalytic = 0.0, worstFd = 0.0;
  int evaluations = 0;
  std::string message() const {
    std::ostringstream s;
    s.precision(6);
    s << "tangent vs central differences: relative error " << relativeError << " (tolerance "
      << tolerance << "), estimated finite-difference error " << fdError << ", ||J||_F " << norm
      << "; worst entry (row " << worstRow << ", column " << worstCol << "): analytic "
      << worstAnalytic << ", finite differences " << worstFd << " (" << evaluations
      << " residual evaluations)";
    if (fdError > tolerance) s << "; the finite differences are no reference at this state (a kink within h?)";
    return s.str();
  }
};

inline double fdStep(const std::vector<double>& x, const TangentCheckOptions& o, int j) {
  const double s = o.scales.empty() ? o.scale : o.scales[size_t(j)];
  return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(x[size_t(j)]), s);
}

// Central differences of R at x with steps factor * h_j (1); `roundoff` (if given) receives
// per entry the round-off estimate eps max(|R(x +- h e_j)|, residualScale) / h.
inline Dense centralDifferences(const Residual& R, const std::vector<double>& x, int m,
                                const TangentCheckOptions& o, double factor, Dense* roundoff,
                                int& evaluations) {
  const int n = int(x.size());
  Dense D(m, n);
  if (roundoff) *roundoff = Dense(m, n);
  std::vector<double> xp = x;
  const double eps = std::numeric_limits<double>::epsilon();
  for (int j = 0; j < n; ++j) {
    const double h = factor * fdStep(x, o, j);
    xp[size_t(j)] = x[size_t(j)] + h;
    const std::vector<double> rp = R(xp);
    xp[size_t(j)] = x[size_t(j)] - h;
    const std::vector<double> rm = R(xp);
    xp[size_t(j)] = x[size_t(j)];
    evaluations += 2;
    const double h2 = (x[size_t(j)] + h) - (x[size_t(j)] - h);  // the step actually taken
    for (int i = 0; i < m; ++i) {
      D(i, j) = (rp[size_t(i)] - rm[size_t(i)]) / h2;
      // Round-off where the two evaluations differ (an entry whose row did not move is 0
      // exactly: x_j does not enter R_i, or a row that is exactly zero).
      const bool terms = rp[size_t(i)] != rm[size_t(i)];
      if (roundoff && terms)
        (*roundoff)(i, j) =
            eps * std::max({std::abs(rp[size_t(i)]), std::abs(rm[size_t(i)]), o.residualScale}) / h;
    }
  }
  return D;
}

// The check of J (m x n, m = R(x).size(), n = x.size()) against central differences of R at x.
inline TangentCheck checkTangent(const Residual& R, const Dense& J, const std::vector<double>& x,
                                 const TangentCheckOptions& o = {}) {
  TangentCheck c;
  c.tolerance = o.tolerance;
  const std::vector<double> r0 = R(x);
  c.evaluations = 1;
  const int m = int(r0.size()), n = int(x.size());
  if (J.rows != m || J.cols != n) {
    c.relativeError = INFINITY;
    c.fdError = 0.0;
    return c;
  }
  Dense roundoff;
  const Dense D = centralDifferences(R, x, m, o, 1.0, &roundoff, c.evaluations);
  const Dense D2 = centralDifferences(R, x, m, o, 2.0, nullptr, c.evaluations);
  double diff = 0.0, est = 0.0, worst = -1.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double d = J(i, j) - D(i, j);
      diff += d * d;
      const double e = std::abs(D2(i, j) - D(i, j)) + roundoff(i, j);
      est += e * e;
      if (std::abs(d) > worst) {
        worst = std::abs(d);
        c.worstRow = i, c.worstCol = j, c.worstAnalytic = J(i, j), c.worstFd = D(i, j);
      }
    }
  c.norm = J.frobenius();
  const double ref = std::max(c.norm, D.frobenius());
  c.relativeError = ref > 0 ? std::sqrt(diff) / ref : 0.0;
  c.fdError = ref > 0 ? std::sqrt(est) / ref : 0.0;
  c.passed = c.relativeError <= c.tolerance && c.fdError <= c.tolerance;
  return c;
}

// J plus `relative` ||J||_F on entry (i, j) (by default its largest entry): a tangent that must
// fail the check.
inline Dense perturbed(const Dense& J, double relative = 1e-3, int i = -1, int j = -1) {
  Dense P = J;
  if (i < 0 || j < 0) {
    size_t k = 0;
    for (size_t q = 0; q < J.a.size(); ++q)
      if (std::abs(J.a[q]) > std::abs(J.a[k])) k = q;
    i = int(k / size_t(J.cols)), j = int(k % size_t(J.cols));
  }
  P(i, j) += relative * J.frobenius();
  return P;
}

// J without the entries `drop(i, j)` selects (a dropped term).
inline Dense withoutEntries(const Dense& J, const std::function<bool(int, int)>& drop) {
  Dense P = J;
  for (int i = 0; i < J.rows; ++i)
    for (int j = 0; j < J.cols; ++j)
      if (drop(i, j)) P(i, j) = 0.0;
  return P;
}

// For EXPECT_TRUE: the tangent passes the check (the report says by how much).
inline ::testing::AssertionResult tangentMatches(const Residual& R, const Dense& J, const std::vector<double>& x,
                                                 const TangentCheckOptions& o = {}, TangentCheck* out = nullptr) {
  const TangentCheck c = checkTangent(R, J, x, o);
  if (out) *out = c;
  if (c.passed) return ::testing::AssertionSuccess() << c.message();
  return ::testing::AssertionFailure() << c.message();
}

// For EXPECT_TRUE: the (perturbed) tangent fails the check by its error, while the finite
// differences themselves are accurate (a failure for the right reason).
inline ::testing::AssertionResult tangentMismatches(const Residual& R, const Dense& J, const std::vector<double>& x,
                                                    const TangentCheckOptions& o = {}) {
  const TangentCheck c = checkTangent(R, J, x, o);
  if (!c.passed && c.relativeError > c.tolerance && c.fdError <= c.tolerance)
    return ::testing::AssertionSuccess() << c.message();
  return ::testing::AssertionFailure() << "the perturbed tangent was not caught: " << c.message();
}

// ||A - B||_F / max(||A||_F, ||B||_F); (wi, wj) receive the worst entry.
inline double relativeDifference(const Dense& A, const Dense& B, int* wi = nullptr, int* wj = nullptr) {
  if (A.rows != B.rows || A.cols != B.cols) return INFINITY;
  double diff = 0.0, worst = -1.0;
  for (int i = 0; i < A.rows; ++i)
    for (int j = 0; j < A.cols; ++j) {
      const double d = A(i, j) - B(i, j);
      diff += d * d;
      if (std::abs(d) > worst) {
        worst = std::abs(d);
        if (wi) *wi = i;
        if (wj) *wj = j;
      }
    }
  const double ref = std::max(A.frobenius(), B.frobenius());
  return ref > 0 ? std::sqrt(diff) / ref : 0.0;
}

// Two matrices equal to `tolerance` in relativeDifference (an analytic tangent against
// another), reporting the worst entry.
inline ::testing::AssertionResult matricesMatch(const Dense& A, const Dense& B, double tolerance) {
  int wi = -1, wj = -1;
  const double e = relativeDifference(A, B, &wi, &wj);
  std::ostringstream s;
  s << "relative difference " << e << " (tolerance " << tolerance << ")";
  if (wi >= 0) s << ", worst entry (" << wi << ", " << wj << "): " << A(wi, wj) << " vs " << B(wi, wj);
  if (e <= tolerance) return ::testing::AssertionSuccess() << s.str();
  return ::testing::AssertionFailure() << s.str();
}

// The rows this rank owns of a CRS matrix whose global ids are 0 .. rows-1 and 0 .. cols-1,
// dense (the small systems of a unit test, on one rank).
inline Dense denseOf(const CrsMatrix& A, int rows, int cols) {
  Dense D(rows, cols);
  const auto& rowMap = *A.getRowMap();
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t l = 0; l < rowMap.getNodeNumElements(); ++l) {
    const GO g = rowMap.getGlobalElement(LO(l));
    const size_t k = A.getNumEntriesInGlobalRow(g);
    ci.resize(k);
    cv.resize(k);
    size_t got = 0;
    A.getGlobalRowCopy(g, ci(), cv(), got);
    for (size_t q = 0; q < got; ++q) D(int(g), int(ci[q])) += cv[q];
  }
  return D;
}

// std::vector <-> Tpetra vector on a one-rank map (the local entries in order).
inline RCP<Vector> tpetraOf(const std::vector<double>& x, const RCP<const Map>& map) {
  auto v = rcp(new Vector(map));
  auto d = v->getDataNonConst();
  for (size_t i = 0; i < size_t(d.size()); ++i) d[i] = x[i];
  return v;
}

inline std::vector<double> valuesOf(const Vector& v) {
  auto d = v.getData();
  return std::vector<double>(d.begin(), d.end());
}

}  // namespace choc::test
