// The consistent tangent of F-bar's internal force (FiniteStrainSolid.hpp), which Newton needs
// in the implicit schemes. With Fbar = s F at each point, s = (Jbar / J)^(1/3), and the force
//
//   f . du = sum_q w [ s P : dF + p (B . du - F^-T : dF) ],   p = (P : Fbar) / 3,
//
// (P = P(Fbar), B = d ln Jbar / du over the element DOFs), its derivative along Du is, with
// e = B . Du - F^-T : DF, DFbar = s (DF + e F / 3), DP = A : DFbar (A = dP/dFbar, the material's
// tangent: algorithmic for a plastic point) and Dp = (DP : Fbar + P : DFbar) / 3,
//
//   du . K Du = sum_q w [ (s/3) e (P : dF) + s DP : dF - Dp (F^-T : dF) + p tr(F^-1 DF F^-1 dF)
//                         + Dp (B . du) ]
//             + (sum_q w p) [ -(B . Du)(B . du) + (1 / Jbar V) sum_q w J ((F^-T : DF)(F^-T : dF)
//                                                                   - tr(F^-1 DF F^-1 dF)) ],
//
// the last line the derivative of B itself (Jbar V = sum_q w J). Symmetric when A has the major
// symmetry: hyperelastic (the second derivative of int W(Fbar) dV) and J2's algorithmic tangent.
// Dense in the element (B couples every node): 24 x 24 for HEX8. Checked against central
// differences of the force (test_fem_finite_strain.cpp, FBar.*).
#pragma once
#include <vector>

#include "fem/DenseMatrix.hpp"
#include "materials/Tensor2.hpp"

namespace choc {

// One row a of F-bar's pair terms (FBarTangent::rowTerms): with wsDPg = w s DP_b : dF_a and trHH =
// tr(F^-1 dF_b F^-1 dF_a), K_ab += entry(...) and the dilatation's (a, b) += dilation(...).
struct FBarPairTerms {
  double ws, alpha, beta, wp, wJda, wJ;
  double entry(double wsDPg, double eb, double Dpb, double trHH) const {
    return wsDPg + alpha * eb + beta * Dpb + wp * trHH;
  }
  double dilation(double db, double trHH) const { return wJda * db - wJ * trHH; }
};

class FBarTangent {
 public:
  // dofs: the element's DOFs; B: d ln Jbar / du (dofs numbers); JV: sum_q w J.
  FBarTangent(int dofs, const std::vector<double>& B, double JV);

  // One point's terms. G: dF/du_k as 9 numbers (row-major, [3 i + J]) per DOF k (dofs x 9);
  // F, Finv and J the point's own deformation gradient, its inverse and determinant; Fbar, s:
  // the material's F and (Jbar / J)^(1/3); P = P(Fbar); A[3 i + J][3 k + L] = dP_iJ / dFbar_kL.
  void addPoint(const std::vector<double>& G, const Mat3& F, const Mat3& Finv, double J, const Mat3& Fbar, double s,
                const Mat3& P, const double (*A)[9], double w, DenseMatrix& K);
  // The derivative of B, once every point is added.
  void finish(DenseMatrix& K) const;

 private:
  int n_;
  const std::vector<double>& B_;  // the caller's, alive while the tangent is assembled
  double JV_;
  double pressureSum_ = 0.0;     // sum_q w p
  std::vector<double> dilation_;  // sum_q w J ((F^-T : DF)(F^-T : dF) - tr(F^-1 DF F^-1 dF)), n x n
  // One point's per-DOF terms: p, F^-T : dF_k, e_k, P : dF_k, Dp_k, DP_k (9), F^-1 dF_k (9), the row
  // of F that DOF k moves (-1: several) and c_k,i = (dF_k F^-1)_(row, i).
  // (One per thread, reused from element to element.)
  struct Point {
    double p = 0.0;
    std::vector<double> d, e, PG, Dp, DP, H, c;
    std::vector<double> DPt, ct, crow;  // addPairsByRows' column-contiguous copies of DP and c
    std::vector<int> row;
  };
  static Point& scratch();
  Point& point_ = scratch();
  void addPairs(const std::vector<double>& G, double s, double J, double w, DenseMatrix& K);
  void addPairsByRows(const std::vector<double>& G, double s, double J, double w, DenseMatrix& K);
  // Row a's coefficients of its pairs' terms (header): w [ s/3 e_b (P : dF_a) + s DP_b : dF_a +
  // Dp_b (B_a - d_a) + p tr ], and of the dilatation, w J (d_b d_a - tr); both paths use them
  // through FBarPairTerms' two entries.
  FBarPairTerms rowTerms(size_t a, double s, double J, double w) const {
    const Point& t = point_;
    return {w * s, w * s / 3 * t.PG[a], w * (B_[a] - t.d[a]), w * t.p, w * J * t.d[a], w * J};
  }
};

}  // namespace choc
