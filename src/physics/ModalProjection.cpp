#include "physics/ModalProjection.hpp"

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"

namespace choc {

std::vector<double> projectOnBasis(const MultiVector& Phi, const CrsMatrix& M, const Vector& u,
                                   const std::string& method) {
  const int n = static_cast<int>(Phi.getNumVectors());
  std::vector<double> q(n, 0.0);
  if (method == "mass-weighted") {
    Vector Mu(M.getRangeMap());
    M.apply(u, Mu);
    for (int k = 0; k < n; ++k) q[k] = Phi.getVector(k)->dot(Mu);
    return q;
  }
  // Least squares: normal equations of size n (n = number of modes, small).
  std::vector<double> G(size_t(n) * n);
  for (int i = 0; i < n; ++i) {
    q[i] = Phi.getVector(i)->dot(u);
    for (int j = 0; j <= i; ++j) G[size_t(i) * n + j] = G[size_t(j) * n + i] = Phi.getVector(i)->dot(*Phi.getVector(j));
  }
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRF('L', n, G.data(), n, &info);
  if (info != 0) throw NumericalError("least-squares projection: the basis is rank deficient");
  lapack.POTRS('L', n, 1, G.data(), n, q.data(), n, &info);
  return q;
}

void expandOnBasis(const MultiVector& Phi, const std::vector<double>& q, Vector& u) {
  u.putScalar(0.0);
  for (size_t k = 0; k < q.size(); ++k) u.update(q[k], *Phi.getVector(k), 1.0);
}

double projectionResidual(const MultiVector& Phi, const Vector& u, const std::vector<double>& q) {
  Vector r(u, Teuchos::Copy);
  for (size_t k = 0; k < q.size(); ++k) r.update(-q[k], *Phi.getVector(k), 1.0);
  const double nu = u.norm2();
  return nu > 0 ? r.norm2() / nu : 0.0;
}

}  // namespace choc
