#include "contact/MortarSegments.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Teuchos_LAPACK.hpp>

#include "contact/MortarIntegration.hpp"

namespace choc {

using mortar::FaceIn;

bool mortarSlaveFace(const Face& f) {
  return f.edgeNodes ? f.edgeNodes == 2 : f.shape == SolidShape::Tri3 || f.shape == SolidShape::Quad4;
}

Point3 nodeNormal(const Face& f, int a) { return mortar::nodeNormalOf(FaceIn<double>{f, f.x}, a); }

DenseMatrix dualBasis(const Face& s, bool axisymmetric) {
  if (!mortarSlaveFace(s))
    throw std::invalid_argument("mortar takes TRI3, QUAD4 and LINE2 slave faces");
  const int n = static_cast<int>(s.nodes.size());
  std::vector<double> Mv, D;
  mortar::dualBasisIntegrals(FaceIn<double>{s, s.x}, axisymmetric, Mv, D);
  // A = D M^-1; M symmetric positive definite: A^T = M^-1 D by Cholesky (column-major Y = A^T).
  std::vector<double> Mc(size_t(n) * n), Y(size_t(n) * n, 0.0);
  for (int a = 0; a < n; ++a) {
    Y[size_t(a) * n + a] = D[a];
    for (int b = 0; b < n; ++b) Mc[size_t(b) * n + a] = Mv[size_t(a) * n + b];
  }
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POSV('L', n, n, Mc.data(), n, Y.data(), n, &info);
  if (info != 0) throw std::invalid_argument("degenerate slave face");
  DenseMatrix A(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) A(a, b) = Y[size_t(a) * n + b];  // A(a, b) = Y(b, a)
  return A;
}

std::vector<double> dualShapes(const DenseMatrix& A, const std::vector<double>& N) {
  std::vector<double> phi(A.rows(), 0.0);
  for (int a = 0; a < A.rows(); ++a)
    for (int b = 0; b < A.cols(); ++b) phi[a] += A(a, b) * N[b];
  return phi;
}

std::vector<MortarPoint> mortarPoints(const Face& s, const Face& m, bool axisymmetric) {
  return mortar::overlapPoints(FaceIn<double>{s, s.x}, FaceIn<double>{m, m.x}, axisymmetric);
}

}  // namespace choc
