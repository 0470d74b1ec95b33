// Small dense linear-algebra helpers for the element tests (independent of the code tested).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "fem/DenseMatrix.hpp"
#include "mesh/Mesh.hpp"

namespace choc::test {

using Vec = std::vector<double>;

inline double maxAbs(const DenseMatrix& A) {
  double m = 0.0;
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < A.cols(); ++j) m = std::max(m, std::fabs(A(i, j)));
  return m;
}

inline double maxAbs(const Vec& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

inline Vec multiply(const DenseMatrix& A, const Vec& x) {
  Vec y(A.rows(), 0.0);
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < A.cols(); ++j) y[i] += A(i, j) * x[j];
  return y;
}

inline double quadratic(const DenseMatrix& A, const Vec& x) {
  const Vec y = multiply(A, x);
  double s = 0.0;
  for (size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
  return s;
}

inline double asymmetry(const DenseMatrix& A) {
  double m = 0.0;
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < i; ++j) m = std::max(m, std::fabs(A(i, j) - A(j, i)));
  return m;
}

// Eigenvalues of a symmetric matrix by the cyclic Jacobi method, ascending.
inline Vec symmetricEigenvalues(DenseMatrix A) {
  const int n = A.rows();
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0, diag = 0.0;
    for (int i = 0; i < n; ++i) {
      diag += A(i, i) * A(i, i);
      for (int j = 0; j < n; ++j)
        if (i != j) off += A(i, j) * A(i, j);
    }
    if (off <= 1e-30 * diag) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (A(p, q) == 0.0) continue;
        const double theta = (A(q, q) - A(p, p)) / (2.0 * A(p, q));
        const double t = (theta >= 0 ? 1.0 : -1.0) /
                         (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) {  // columns p, q
          const double akp = A(k, p), akq = A(k, q);
          A(k, p) = c * akp - s * akq;
          A(k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // rows p, q
          const double apk = A(p, k), aqk = A(q, k);
          A(p, k) = c * apk - s * aqk;
          A(q, k) = s * apk + c * aqk;
        }
      }
  }
  Vec ev(n);
  for (int i = 0; i < n; ++i) ev[i] = A(i, i);
  std::sort(ev.begin(), ev.end());
  return ev;
}

// Solves A x = b by Gaussian elimination with partial pivoting (A square).
inline Vec solve(DenseMatrix A, Vec b) {
  const int n = A.rows();
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(A(i, k)) > std::fabs(A(p, k))) p = i;
    if (A(p, k) == 0.0) throw std::runtime_error("singular matrix in test solve");
    if (p != k) {
      for (int j = 0; j < n; ++j) std::swap(A(k, j), A(p, j));
      std::swap(b[k], b[p]);
    }
    for (int i = k + 1; i < n; ++i) {
      const double f = A(i, k) / A(k, k);
      for (int j = k; j < n; ++j) A(i, j) -= f * A(k, j);
      b[i] -= f * b[k];
    }
  }
  Vec x(n);
  for (int i = n - 1; i >= 0; --i) {
    double s = b[i];
    for (int j = i + 1; j < n; ++j) s -= A(i, j) * x[j];
    x[i] = s / A(i, i);
  }
  return x;
}

inline Point3 cross3(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double dot3(const Point3& a, const Point3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// A proper rotation (det +1) from Rodrigues' formula about a non-trivial axis.
inline std::array<Point3, 3> someRotation() {
  Point3 k = {0.3, -0.5, 0.81};
  const double n = std::sqrt(dot3(k, k));
  for (double& v : k) v /= n;
  const double a = 0.7, c = std::cos(a), s = std::sin(a);
  std::array<Point3, 3> R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double K = (i == j) ? 0.0 : ((3 + j - i) % 3 == 1 ? -1.0 : 1.0) * k[3 - i - j];
      R[i][j] = c * (i == j) + s * K + (1 - c) * k[i] * k[j];
    }
  return R;
}

inline Point3 rotate(const std::array<Point3, 3>& R, const Point3& x) {
  return {dot3(R[0], x), dot3(R[1], x), dot3(R[2], x)};
}

// The 6 rigid-body modes of nodes x carrying `nc` components per node (3: translations only,
// 6: translations then rotations): 3 translations, then 3 infinitesimal rotations about p.
inline std::vector<Vec> rigidBodyModes(const std::vector<Point3>& x, int nc, const Point3& p) {
  std::vector<Vec> modes;
  for (int d = 0; d < 3; ++d) {
    Vec r(x.size() * nc, 0.0);
    for (size_t a = 0; a < x.size(); ++a) r[a * nc + d] = 1.0;
    modes.push_back(r);
  }
  for (int d = 0; d < 3; ++d) {
    Point3 w = {0, 0, 0};
    w[d] = 1.0;
    Vec r(x.size() * nc, 0.0);
    for (size_t a = 0; a < x.size(); ++a) {
      const Point3 rel = {x[a][0] - p[0], x[a][1] - p[1], x[a][2] - p[2]};
      const Point3 u = cross3(w, rel);
      for (int i = 0; i < 3; ++i) r[a * nc + i] = u[i];
      if (nc == 6)
        for (int i = 0; i < 3; ++i) r[a * nc + 3 + i] = w[i];
    }
    modes.push_back(r);
  }
  return modes;
}

}  // namespace choc::test
