// Eigenvalues and orthonormal eigenvectors of a symmetric 3 x 3 matrix by cyclic Jacobi
// rotations: accurate to round-off in every eigenvector also when eigenvalues coincide (each
// rotation is orthogonal, so the vectors stay orthonormal to eps), which the finite-strain
// plasticity's principal-axis algorithm relies on.
#pragma once
#include <cmath>

#include "materials/Tensor2.hpp"

namespace choc {

struct SymmetricEigen {
  double values[3];
  Mat3 vectors;  // vectors[i][A]: component i of eigenvector A
};

// a must be symmetric. Sweeps until every off-diagonal entry is below eps of the diagonal's
// size (at most 50 sweeps; a 3 x 3 matrix takes 4-6).
inline SymmetricEigen symmetricEigen(const Mat3& a) {
  Mat3 m = a;
  SymmetricEigen r{{0, 0, 0}, identity3()};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = m[0][1] * m[0][1] + m[1][2] * m[1][2] + m[0][2] * m[0][2];
    const double diag = m[0][0] * m[0][0] + m[1][1] * m[1][1] + m[2][2] * m[2][2];
    if (off <= 1e-32 * diag || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (m[p][q] == 0.0) continue;
        const double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {  // m <- m J (columns p, q)
          const double mkp = m[k][p], mkq = m[k][q];
          m[k][p] = c * mkp - s * mkq;
          m[k][q] = s * mkp + c * mkq;
        }
        for (int k = 0; k < 3; ++k) {  // m <- J^T m (rows p, q)
          const double mpk = m[p][k], mqk = m[q][k];
          m[p][k] = c * mpk - s * mqk;
          m[q][k] = s * mpk + c * mqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = r.vectors[k][p], vkq = r.vectors[k][q];
          r.vectors[k][p] = c * vkp - s * vkq;
          r.vectors[k][q] = s * vkp + c * vkq;
        }
      }
  }
  for (int A = 0; A < 3; ++A) r.values[A] = m[A][A];
  return r;
}

}  // namespace choc
