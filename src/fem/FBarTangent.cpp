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
  t.d.assign(n, 0.0), t.e.resize(n), t.PG.assign(n, 0.0), t.Dp.resize(n), t.DP.resize(9 * n);
  t.row.resize(n), t.c.resize(3 * n);
  t.p = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int J2 = 0; J2 < 3; ++J2) t.p += P[i][J2] * Fbar[i][J2] / 3;
  bool rows = true;  // then F^-1 dF_k (H) is not needed
  for (size_t k = 0; k < n; ++k) rows = (t.row[k] = singleRow(&G[9 * k])) >= 0 && rows;
  if (!rows) t.H.assign(9 * n, 0.0);
  // A : F and P : F, once: DFbar_k = s (dF_k + e_k / 3 F) makes DP_k = s (A : dF_k + e_k / 3 A : F)
  // and P : DFbar_k = s (P : dF_k + e_k / 3 P : F), with A : dF_k over dF_k's one row when it has one.
  double AF[9], PF = 0.0;
  for (int r = 0; r < 9; ++r) {
    AF[r] = 0.0;
    for (int c = 0; c < 9; ++c) AF[r] += A[r][c] * F[c / 3][c % 3];
    PF += P[r / 3][r % 3] * F[r / 3][r % 3];
  }
  for (size_t k = 0; k < n; ++k) {
    const double* g = &G[9 * k];
    double* h = rows ? nullptr : &t.H[9 * k];  // F^-1 dF_k (H is empty when every DOF moves one row)
    for (int i = 0; i < 3; ++i)
      for (int L = 0; L < 3; ++L) {
        const double gi = g[3 * i + L];
        if (gi == 0.0) continue;
        t.d[k] += Finv[L][i] * gi;
        t.PG[k] += P[i][L] * gi;
        for (int Jr = 0; Jr < 3 && !rows; ++Jr) h[3 * Jr + L] += Finv[Jr][i] * gi;
      }
    t.e[k] = B_[k] - t.d[k];
    const double third = t.e[k] / 3;
    double dp = s * (t.PG[k] + third * PF);  // P : DFbar_k
    double* DP = &t.DP[9 * k];
    if (t.row[k] >= 0) {  // dF_k's entries on its one row
      const int c0 = 3 * t.row[k];
      for (int r = 0; r < 9; ++r)
        DP[r] = s * (A[r][c0] * g[c0] + A[r][c0 + 1] * g[c0 + 1] + A[r][c0 + 2] * g[c0 + 2] + third * AF[r]);
    } else {
      for (int r = 0; r < 9; ++r) {
        double Ag = 0.0;
        for (int c = 0; c < 9; ++c) Ag += A[r][c] * g[c];
        DP[r] = s * (Ag + third * AF[r]);
      }
    }
    for (int r = 0; r < 9; ++r) dp += DP[r] * Fbar[r / 3][r % 3];
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
    const FBarPairTerms terms = rowTerms(a, s, J, w);
    for (size_t b = 0; b < n; ++b) {
      const double* hb = &t.H[9 * b];
      const double* DPb = &t.DP[9 * b];
      double DPg = 0.0, trHH = 0.0;
      for (int r = 0; r < 9; ++r) DPg += DPb[r] * ga[r];
      for (int Jr = 0; Jr < 3; ++Jr)
        for (int L = 0; L < 3; ++L) trHH += hb[3 * Jr + L] * ha[3 * L + Jr];
      K(int(a), int(b)) += terms.entry(terms.ws * DPg, t.e[b], t.Dp[b], trHH);
      dilation_[a * n + b] += terms.dilation(t.d[b], trHH);
    }
  }
}

namespace {

// One row a of addPairsByRows over the columns b (unit strides, independent: vectorised); g0..g2
// are dF_a's row times w s.
void addRow(int n, const FBarPairTerms& t, double g0, double g1, double g2, const double* __restrict D0,
            const double* __restrict D1, const double* __restrict D2, const double* __restrict e,
            const double* __restrict Dp, const double* __restrict d, const double* __restrict cb,
            const double* __restrict crow, double* __restrict Ka, double* __restrict Da) {
  const FBarPairTerms terms = t;  // a local copy: no store below can change it
  for (int b = 0; b < n; ++b) {
    const double trHH = cb[b] * crow[b];
    Ka[b] += terms.entry(D0[b] * g0 + D1[b] * g1 + D2[b] * g2, e[b], Dp[b], trHH);
    Da[b] += terms.dilation(d[b], trHH);
  }
}

}  // namespace

// The same when every DOF moves one row of F (row_k): DP : dF_a reads row_a's three entries, and
// F^-1 dF_k = F^-1 e_row ⊗ g is of rank one, so tr(F^-1 dF_b F^-1 dF_a) = c_b,row_a c_a,row_b.
// Row a of K is then alpha_a e + beta_a Dp + w s (DP : dF_a) + w p trHH over the columns b, with
// DP's and c's entries copied column-contiguous first (the loop over b reads only unit strides).
void FBarTangent::addPairsByRows(const std::vector<double>& G, double s, double J, double w, DenseMatrix& K) {
  const size_t n = size_t(n_);
  Point& t = point_;
  t.DPt.resize(9 * n), t.ct.resize(3 * n), t.crow.resize(n);
  for (size_t b = 0; b < n; ++b) {
    for (size_t r = 0; r < 9; ++r) t.DPt[r * n + b] = t.DP[9 * b + r];
    for (size_t r = 0; r < 3; ++r) t.ct[r * n + b] = t.c[3 * b + r];
  }
  const double* __restrict e = t.e.data();
  const double* __restrict Dp = t.Dp.data();
  const double* __restrict d = t.d.data();
  double* __restrict crow = t.crow.data();
  for (size_t a = 0; a < n; ++a) {
    const size_t ra = size_t(t.row[a]);
    const double* ga = &G[9 * a + 3 * ra];
    const FBarPairTerms terms = rowTerms(a, s, J, w);
    const double* __restrict D0 = &t.DPt[(3 * ra) * n];
    const double* __restrict D1 = D0 + n;
    const double* __restrict D2 = D1 + n;
    const double* __restrict cb = &t.ct[ra * n];
    for (size_t b = 0; b < n; ++b) crow[b] = t.c[3 * a + size_t(t.row[b])];  // c_a,row_b
    addRow(int(n), terms, terms.ws * ga[0], terms.ws * ga[1], terms.ws * ga[2], D0, D1, D2, e, Dp, d, cb, crow,
           &K(int(a), 0), &dilation_[a * n]);
  }
}

void FBarTangent::finish(DenseMatrix& K) const {
  const size_t n = size_t(n_);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b)
      K(int(a), int(b)) += pressureSum_ * (dilation_[a * n + b] / JV_ - B_[b] * B_[a]);
}

}  // namespace choc
