#include "solvers/PreconditionedGmres.hpp"

#include <cmath>
#include <vector>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

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
  std::vector<RCP<Vector>> V;
  V.push_back(rcp(new Vector(r0, Teuchos::Copy)));
  V[0]->scale(1.0 / beta);
  // H is (m+1) x m, stored by columns; cs/sn: the Givens rotations; g: the rotated residual.
  std::vector<std::vector<double>> H;
  std::vector<double> cs, sn, g{beta};
  Vector z(map), w(map);
  int m = 0;
  for (; m < maxIterations; ++m) {
    out.failure = precondition(*V[m], z);
    if (!out.failure.empty()) return out;
    A.apply(z, w);
    std::vector<double> h(m + 2, 0.0);
    for (int i = 0; i <= m; ++i) {
      h[i] = w.dot(*V[i]);
      w.update(-h[i], *V[i], 1.0);
    }
    h[m + 1] = w.norm2();
    for (int i = 0; i < m; ++i) {  // earlier rotations
      const double t = cs[i] * h[i] + sn[i] * h[i + 1];
      h[i + 1] = -sn[i] * h[i] + cs[i] * h[i + 1];
      h[i] = t;
    }
    const double r = std::hypot(h[m], h[m + 1]);
    if (!(r > 0.0)) break;  // breakdown: the solution lies in the current space
    cs.push_back(h[m] / r);
    sn.push_back(h[m + 1] / r);
    g.push_back(-sn[m] * g[m]);
    g[m] = cs[m] * g[m];
    const double next = h[m + 1];
    h[m] = r;
    h[m + 1] = 0.0;
    H.push_back(std::move(h));
    out.estimatedResidual = std::fabs(g[m + 1]) / bnorm;
    if (!std::isfinite(out.estimatedResidual)) return out;
    if (out.estimatedResidual <= tol) {
      ++m;
      break;
    }
    V.push_back(rcp(new Vector(w, Teuchos::Copy)));
    V.back()->scale(1.0 / next);
  }
  out.iterations = m;
  // y = H^-1 g (upper triangular), x = P^-1 (V y).
  std::vector<double> y(m, 0.0);
  for (int i = m - 1; i >= 0; --i) {
    double s = g[i];
    for (int j = i + 1; j < m; ++j) s -= H[j][i] * y[j];
    y[i] = s / H[i][i];
  }
  w.putScalar(0.0);
  for (int i = 0; i < m; ++i) w.update(y[i], *V[i], 1.0);
  out.failure = precondition(w, z);
  x.update(1.0, z, 1.0);
  out.converged = out.failure.empty() && out.estimatedResidual <= tol;
  return out;
}

}  // namespace choc
