// F-bar's consistent tangent (see FBarTangent.hpp for the terms).
#include "fem/FBarTangent.hpp"

namespace choc {

FBarTangent::FBarTangent(int dofs, const std::vector<double>& B, double JV)
    : n_(dofs), B_(B), JV_(JV), dilation_(size_t(dofs) * size_t(dofs), 0.0) {}

void FBarTangent::addPoint(const std::vector<double>& G, const Mat3& F, const Mat3& Finv, double J, const Mat3& Fbar,
                           double s, const Mat3& P, const double (*A)[9], double w, DenseMatrix& K) {
  const size_t n = size_t(n_);
  thread_local std::vector<double> d, e, PG, Dp, DP, H;
  d.assign(n, 0.0), e.resize(n), PG.assign(n, 0.0), Dp.resize(n), DP.resize(9 * n), H.assign(9 * n, 0.0);
  double p = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int J2 = 0; J2 < 3; ++J2) p += P[i][J2] * Fbar[i][J2] / 3;
  for (size_t k = 0; k < n; ++k) {
    const double* g = &G[9 * k];
    double* h = &H[9 * k];  // F^-1 dF_k
    for (int i = 0; i < 3; ++i)
      for (int L = 0; L < 3; ++L) {
        const double gi = g[3 * i + L];
        if (gi == 0.0) continue;
        d[k] += Finv[L][i] * gi;
        PG[k] += P[i][L] * gi;
        for (int Jr = 0; Jr < 3; ++Jr) h[3 * Jr + L] += Finv[Jr][i] * gi;
      }
    e[k] = B_[k] - d[k];
    double Fb[9];  // dFbar / du_k
    for (int r = 0; r < 9; ++r) Fb[r] = s * (g[r] + e[k] / 3 * F[r / 3][r % 3]);
    double dp = 0.0;
    for (int r = 0; r < 9; ++r) {
      double v = 0.0;
      for (int c = 0; c < 9; ++c) v += A[r][c] * Fb[c];
      DP[9 * k + size_t(r)] = v;
      dp += v * Fbar[r / 3][r % 3] + P[r / 3][r % 3] * Fb[r];
    }
    Dp[k] = dp / 3;
  }
  for (size_t a = 0; a < n; ++a) {  // a: the test direction (row), b: the increment (column)
    const double* ga = &G[9 * a];
    const double* ha = &H[9 * a];
    for (size_t b = 0; b < n; ++b) {
      const double* hb = &H[9 * b];
      const double* DPb = &DP[9 * b];
      double DPg = 0.0, trHH = 0.0;
      for (int r = 0; r < 9; ++r) DPg += DPb[r] * ga[r];
      for (int Jr = 0; Jr < 3; ++Jr)
        for (int L = 0; L < 3; ++L) trHH += hb[3 * Jr + L] * ha[3 * L + Jr];
      K(int(a), int(b)) += w * (s / 3 * e[b] * PG[a] + s * DPg - Dp[b] * d[a] + p * trHH + Dp[b] * B_[a]);
      dilation_[a * n + b] += w * J * (d[b] * d[a] - trHH);
    }
  }
  pressureSum_ += w * p;
}

void FBarTangent::finish(DenseMatrix& K) const {
  const size_t n = size_t(n_);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b)
      K(int(a), int(b)) += pressureSum_ * (dilation_[a * n + b] / JV_ - B_[b] * B_[a]);
}

}  // namespace choc
