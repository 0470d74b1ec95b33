#include "solvers/PreconditionedGmres.hpp"

#include <cmath>
#include <vector>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

namespace {

using Preconditioner = std::function<std::string(const Vector&, Vector&)>;

// The Krylov space: its basis V, the preconditioned basis Z (Z_i = P^-1 V_i, kept so that the
// solution needs no further solve), the Hessenberg matrix H ((m+1) x m, stored by columns, made
// upper triangular by the Givens rotations cs/sn) and the rotated residual g.
struct KrylovSpace {
  std::vector<RCP<Vector>> V, Z;
  std::vector<std::vector<double>> H;
  std::vector<double> cs, sn, g;
};

// Column m of the Hessenberg matrix: w orthogonalised against V[0..m] (modified Gram-Schmidt).
std::vector<double> orthogonalize(Vector& w, const std::vector<RCP<Vector>>& V, int m) {
  std::vector<double> h(m + 2, 0.0);
  for (int i = 0; i <= m; ++i) {
    h[i] = w.dot(*V[i]);
    w.update(-h[i], *V[i], 1.0);
  }
  h[m + 1] = w.norm2();
  return h;
}

// Rotates column h by the earlier rotations and a new one that zeroes h[m + 1], and appends
// it to H; false on breakdown (the solution lies in the current space). next: ||w||, the
// scale of the next basis vector.
bool rotateColumn(std::vector<double> h, KrylovSpace& k, int m, double& next) {
  for (int i = 0; i < m; ++i) {  // earlier rotations
    const double t = k.cs[i] * h[i] + k.sn[i] * h[i + 1];
    h[i + 1] = -k.sn[i] * h[i] + k.cs[i] * h[i + 1];
    h[i] = t;
  }
  const double r = std::hypot(h[m], h[m + 1]);
  if (!(r > 0.0)) return false;
  k.cs.push_back(h[m] / r);
  k.sn.push_back(h[m + 1] / r);
  k.g.push_back(-k.sn[m] * k.g[m]);
  k.g[m] = k.cs[m] * k.g[m];
  next = h[m + 1];
  h[m] = r;
  h[m + 1] = 0.0;
  k.H.push_back(std::move(h));
  return true;
}

// x += Z y = P^-1 (V y) with y = H^-1 g (upper triangular) over the first m columns.
void addCorrection(const KrylovSpace& k, int m, Vector& x) {
  std::vector<double> y(m, 0.0);
  for (int i = m - 1; i >= 0; --i) {
    double s = k.g[i];
    for (int j = i + 1; j < m; ++j) s -= k.H[j][i] * y[j];
    y[i] = s / k.H[i][i];
  }
  for (int i = 0; i < m; ++i) x.update(y[i], *k.Z[i], 1.0);
}

}  // namespace

GmresOutcome preconditionedGmres(const CrsMatrix& A,
                                 const std::function<std::string(const Vector&, Vector&)>& precondition,
                                 const Vector& b, Vector& x, double tol, int maxIterations) {
  GmresOutcome out;
  const double bnorm = b.norm2();
  x.putScalar(0.0);
  if (!(bnorm > 0.0)) {
    out.converged = std::isfinite(bnorm);
    return out;
  }
  auto map = b.getMap();
  // x0 = P^-1 b: exact when A is the preconditioner's matrix (0 iterations).
  out.failure = precondition(b, x);
  if (!out.failure.empty()) return out;
  Vector r0(b, Teuchos::Copy);
  A.apply(x, r0, Teuchos::NO_TRANS, -1.0, 1.0);
  const double beta = r0.norm2();
  out.estimatedResidual = beta / bnorm;
  if (!std::isfinite(beta)) return out;
  if (out.estimatedResidual <= tol) {
    out.converged = true;
    return out;
  }
  KrylovSpace k;
  k.V.push_back(rcp(new Vector(r0, Teuchos::Copy)));
  k.V[0]->scale(1.0 / beta);
  k.g.push_back(beta);
  Vector w(map);
  int m = 0;
  for (; m < maxIterations; ++m) {
    k.Z.push_back(rcp(new Vector(map)));
    out.failure = precondition(*k.V[m], *k.Z[m]);
    if (!out.failure.empty()) return out;
    A.apply(*k.Z[m], w);
    double next = 0.0;
    if (!rotateColumn(orthogonalize(w, k.V, m), k, m, next)) break;
    out.estimatedResidual = std::fabs(k.g[m + 1]) / bnorm;
    if (!std::isfinite(out.estimatedResidual)) return out;
    if (out.estimatedResidual <= tol) {
      ++m;
      break;
    }
    k.V.push_back(rcp(new Vector(w, Teuchos::Copy)));
    k.V.back()->scale(1.0 / next);
  }
  out.iterations = m;
  addCorrection(k, m, x);
  out.converged = out.estimatedResidual <= tol;
  return out;
}

}  // namespace choc
