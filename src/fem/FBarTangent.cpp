// F-bar's consistent tangent (see FBarTangent.hpp for the terms).
#include "fem/FBarTangent.hpp"

namespace choc {

FBarTangent::FBarTangent(int dofs, const std::vector<double>& B, double JV)
    : n_(dofs), B_(B), JV_(JV), dilation_(size_t(dofs) * size_t(dofs), 0.0) {}

FBarTangent::Point& FBarTangent::scratch() {
  thread_local Point point;
  return point;
}

// The row i of dF/du_k when it has one (3D and plane strain: every DOF moves one row of F; a DOF
// without a gradient at the point: row 0, its terms vanish), else -1 (an axisymmetric radial DOF
// moves F_rr, F_rz and the hoop stretch).
static int singleRow(const double* g) {
  int row = -1;
  for (int r = 0; r < 9; ++r) {
    if (g[r] == 0.0) continue;
    if (row >= 0 && row != r / 3) return -1;
    row = r / 3;
  }
  return row < 0 ? 0 : row;
}

void FBarTangent::addPoint(const std::vector<double>& G, const Mat3& F, const Mat3& Finv, double J, const Mat3& Fbar,
                           double s, const Mat3& P, const double (*A)[9], double w, DenseMatrix& K) {
  const size_t n = size_t(n_);
  Point& t = point_;
  t.d.assign(n, 0.0), t.e.resize(n), t.PG.assign(n, 0.0), t.Dp.resize(n), t.DP.resize(9 * n), t.H.assign(9 * n, 0.0);
  t.row.resize(n), t.c.resize(3 * n);
  t.p = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int J2 = 0; J2 < 3; ++J2) t.p += P[i][J2] * Fbar[i][J2] / 3;
  bool rows = true;  // then F^-1 dF_k (H) is not needed
  for (size_t k = 0; k < n; ++k) rows = (t.row[k] = singleRow(&G[9 * k])) >= 0 && rows;
  for (size_t k = 0; k < n; ++k) {
    const double* g = &G[9 * k];
    double* h = &t.H[9 * k];  // F^-1 dF_k
    for (int i = 0; i < 3; ++i)
      for (int L = 0; L < 3; ++L) {
        const double gi = g[3 * i + L];
        if (gi == 0.0) continue;
        t.d[k] += Finv[L][i] * gi;
        t.PG[k] += P[i][L] * gi;
        for (int Jr = 0; Jr < 3 && !rows; ++Jr) h[3 * Jr + L] += Finv[Jr][i] * gi;
      }
    t.e[k] = B_[k] - t.d[k];
    double Fb[9];  // dFbar / du_k
    for (int r = 0; r < 9; ++r) Fb[r] = s * (g[r] + t.e[k] / 3 * F[r / 3][r % 3]);
    double dp = 0.0;
    for (int r = 0; r < 9; ++r) {
      double v = 0.0;
      for (int c = 0; c < 9; ++c) v += A[r][c] * Fb[c];
      t.DP[9 * k + size_t(r)] = v;
      dp += v * Fbar[r / 3][r % 3] + P[r / 3][r % 3] * Fb[r];
    }
    t.Dp[k] = dp / 3;
    for (int i = 0; i < 3 && rows; ++i)  // c_k,i = sum_L g_k,(row L) F^-1_Li
      t.c[3 * k + size_t(i)] = g[3 * t.row[k]] * Finv[0][i] + g[3 * t.row[k] + 1] * Finv[1][i] +
                               g[3 * t.row[k] + 2] * Finv[2][i];
  }
  if (rows)
    addPairsByRows(G, s, J, w, K);
  else
    addPairs(G, s, J, w, K);
  pressureSum_ += w * t.p;
}

// Every pair's terms (header) from the full 9-entry products.
void FBarTangent::addPairs(const std::vector<double>& G, double s, double J, double w, DenseMatrix& K) {
  const size_t n = size_t(n_);
  const Point& t = point_;
  for (size_t a = 0; a < n; ++a) {  // a: the test direction (row), b: the increment (column)
    const double* ga = &G[9 * a];
    const double* ha = &t.H[9 * a];
    for (size_t b = 0; b < n; ++b) {
      const double* hb = &t.H[9 * b];
      const double* DPb = &t.DP[9 * b];
      double DPg = 0.0, trHH = 0.0;
      for (int r = 0; r < 9; ++r) DPg += DPb[r] * ga[r];
      for (int Jr = 0; Jr < 3; ++Jr)
        for (int L = 0; L < 3; ++L) trHH += hb[3 * Jr + L] * ha[3 * L + Jr];
      addPair(a, b, s, J, w, DPg, trHH, K);
    }
  }
}

// The same when every DOF moves one row of F (row_k): DP : dF_a reads row_a's three entries, and
// F^-1 dF_k = F^-1 e_row ⊗ g is of rank one, so tr(F^-1 dF_b F^-1 dF_a) = c_b,row_a c_a,row_b.
void FBarTangent::addPairsByRows(const std::vector<double>& G, double s, double J, double w, DenseMatrix& K) {
  const size_t n = size_t(n_);
  const Point& t = point_;
  const double* __restrict e = t.e.data();
  const double* __restrict Dp = t.Dp.data();
  const double* __restrict DP = t.DP.data();
  const double* __restrict c = t.c.data();
  const double* __restrict d = t.d.data();
  const int* __restrict row = t.row.data();
  for (size_t a = 0; a < n; ++a) {
    const size_t ra = size_t(row[a]);
    const double* ga = &G[9 * a + 3 * ra];
    const double g0 = ga[0], g1 = ga[1], g2 = ga[2], PGa = t.PG[a], da = d[a], Ba = B_[a];
    const double* __restrict ca = &c[3 * a];
    double* __restrict Ka = &K(int(a), 0);
    double* __restrict Da = &dilation_[a * n];
    for (size_t b = 0; b < n; ++b) {
      const double* DPb = &DP[9 * b + 3 * ra];
      const double DPg = DPb[0] * g0 + DPb[1] * g1 + DPb[2] * g2;
      const double trHH = c[3 * b + ra] * ca[row[b]];
      Ka[b] += pairTerm(w, s, t.p, e[b], PGa, DPg, Dp[b], da, trHH, Ba);
      Da[b] += w * J * (d[b] * da - trHH);
    }
  }
}

void FBarTangent::finish(DenseMatrix& K) const {
  const size_t n = size_t(n_);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b)
      K(int(a), int(b)) += pressureSum_ * (dilation_[a * n + b] / JV_ - B_[b] * B_[a]);
}

}  // namespace choc
