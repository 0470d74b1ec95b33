// Eigenvalues and orthonormal eigenvectors of a symmetric 3 x 3 matrix by cyclic Jacobi
// rotations: accurate to round-off in every eigenvector also when eigenvalues coincide (each
// rotation is orthogonal, so the vectors stay orthonormal to eps), which the finite-strain
// plasticity's principal-axis algorithm relies on.
//
// Cost (it is most of an explicit plastic point's update): the matrix is kept as its six
// distinct entries and a rotation of (p, q) updates the two diagonal entries by -+ t a_pq and the
// third row's pair by the rotation (Numerical Recipes' form). Once a_pq is small against the
// diagonal's gap d = a_qq - a_pp (|a_pq| < 5e-5 |d|, the quadratic phase that ends every
// decomposition), t and c come from their series in u = a_pq / d: t = u (1 - u^2 (1 - 2 u^2)),
// c = 1 - t^2 (1/2 - 3/8 t^2), whose truncation errors (5 u^6, t^6 / 3) are below 1e-25: one
// division instead of three divisions and two square roots. Before that, t and c are written
// with h = sqrt(d^2 + 4 a_pq^2) so that their two divisions are independent (entries below 1e150
// in magnitude: d^2 must not overflow). A rotation with |t| < 1e-18 would change nothing beyond
// round-off: a_pq is set to zero instead.
#pragma once
#include <cmath>

#include "materials/Tensor2.hpp"

namespace choc {

struct SymmetricEigen {
  double values[3];
  Mat3 vectors;  // vectors[i][A]: component i of eigenvector A
};

// a must be symmetric (its upper triangle is read). Sweeps until every off-diagonal entry is
// below eps of the diagonal's size (at most 50 sweeps; a 3 x 3 matrix takes 4-6).
inline SymmetricEigen symmetricEigen(const Mat3& a) {
  double d[3] = {a[0][0], a[1][1], a[2][2]};
  double o[3] = {a[0][1], a[0][2], a[1][2]};  // o[k]: the entry (p, q) of rotation k below
  constexpr int P[3] = {0, 0, 1}, Q[3] = {1, 2, 2};
  // Rotation k's entries (r, p) and (r, q), r the third index, in o[]: (0, 1): (2, 0) = o[1],
  // (2, 1) = o[2]; (0, 2): (1, 0) = o[0], (1, 2) = o[2]; (1, 2): (0, 1) = o[0], (0, 2) = o[1].
  constexpr int RP[3] = {1, 0, 0}, RQ[3] = {2, 2, 1};
  SymmetricEigen r{{0, 0, 0}, identity3()};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
    const double diag = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (off <= 1e-32 * diag || off == 0.0) break;
    for (int k = 0; k < 3; ++k) {
      const double apq = o[k];
      if (apq == 0.0) continue;
      const int p = P[k], q = Q[k];
      const double gap = d[q] - d[p];
      double t, c;
      if (std::abs(apq) < 5e-5 * std::abs(gap)) {  // the series (header)
        const double u = apq / gap, u2 = u * u;
        t = u * (1 - u2 * (1 - 2 * u2));
        if (std::abs(t) < 1e-18) {
          o[k] = 0.0;
          continue;
        }
        c = 1 - t * t * (0.5 - 0.375 * t * t);
      } else {  // t = sgn(theta) / (|theta| + sqrt(theta^2 + 1)), theta = gap / 2 a_pq, times 2 |a_pq| / 2 |a_pq|
        const double h = std::sqrt(gap * gap + 4 * apq * apq), g = std::abs(gap) + h;
        if (h > 0) {
          t = (gap >= 0 ? 2 * apq : -2 * apq) / g;
          c = std::sqrt(g / (2 * h));  // 1 / sqrt(1 + t^2), with 1 + t^2 = 2 h / g
        } else {  // gap = 0 and a_pq^2 underflows: the rotation by 45 degrees (theta = 0)
          t = 1.0, c = std::sqrt(0.5);
        }
      }
      const double s = t * c;
      d[p] -= t * apq;
      d[q] += t * apq;
      o[k] = 0.0;
      const double arp = o[RP[k]], arq = o[RQ[k]];
      o[RP[k]] = c * arp - s * arq;
      o[RQ[k]] = s * arp + c * arq;
      for (int i = 0; i < 3; ++i) {
        const double vip = r.vectors[i][p], viq = r.vectors[i][q];
        r.vectors[i][p] = c * vip - s * viq;
        r.vectors[i][q] = s * vip + c * viq;
      }
    }
  }
  for (int A = 0; A < 3; ++A) r.values[A] = d[A];
  return r;
}

}  // namespace choc
