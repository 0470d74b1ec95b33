#include "physics/StaticCorrection.hpp"

#include <cmath>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "fem/Components.hpp"
#include "fem/MatrixOps.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {

namespace {

// C = A^T B as a dense column-major array (A: n x a, B: n x b; replicated on every rank).
std::vector<double> transposeProduct(const MultiVector& A, const MultiVector& B) {
  const size_t a = A.getNumVectors(), b = B.getNumVectors();
  auto local = Tpetra::createLocalMapWithNode<LO, GO, typename MultiVector::node_type>(a, A.getMap()->getComm());
  MultiVector C(local, b);
  C.multiply(Teuchos::TRANS, Teuchos::NO_TRANS, 1.0, A, B, 0.0);
  std::vector<double> out(a * b);
  for (size_t j = 0; j < b; ++j) {
    auto col = C.getData(j);
    for (size_t i = 0; i < a; ++i) out[j * a + i] = col[i];
  }
  return out;
}

// Y = X D with D a dense (replicated) k x m column-major matrix.
void multiplyDense(const MultiVector& X, const std::vector<double>& D, size_t k, size_t m, MultiVector& Y) {
  auto local = Tpetra::createLocalMapWithNode<LO, GO, typename MultiVector::node_type>(k, X.getMap()->getComm());
  MultiVector Dm(local, m);
  for (size_t j = 0; j < m; ++j) {
    auto col = Dm.getDataNonConst(j);
    for (size_t i = 0; i < k; ++i) col[i] = D[j * k + i];
  }
  Y.multiply(Teuchos::NO_TRANS, Teuchos::NO_TRANS, 1.0, X, Dm, 0.0);
}

double massNorm(const CrsMatrix& M, const Vector& x) {
  Vector Mx(M.getRangeMap());
  M.apply(x, Mx);
  return std::sqrt(std::max(0.0, x.dot(Mx)));
}

// Unit forces: column j at the node of load j, along its direction.
void fillUnitForces(Model& model, const std::vector<StaticLoad>& loads, MultiVector& F) {
  for (size_t j = 0; j < loads.size(); ++j)
    for (int c : {DX, DY, DZ}) {
      const long long d = model.dof(loads[j].node, c);
      if (d >= 0 && model.map()->isNodeGlobalElement(GO(d)))
        F.replaceGlobalValue(GO(d), j, loads[j].direction[c]);
    }
}

// s of K + s M: 0, or 1 % of the lowest flexible eigenvalue (of the rigid-body limit when
// there is none) when the basis has rigid-body modes.
double staticShift(const ModalBasis& basis, double rigidFrequencyHz) {
  const double rigid = std::pow(2 * M_PI * rigidFrequencyHz, 2);
  double lowestFlexible = 0.0;
  bool hasRigid = false;
  for (double l : basis.eigenvalues) {
    if (l < rigid) hasRigid = true;
    else if (lowestFlexible == 0.0) lowestFlexible = l;
  }
  return hasRigid ? 1e-2 * (lowestFlexible > 0 ? lowestFlexible : rigid) : 0.0;
}

// (K + s M) Psi = F.
void solveStaticResponses(RCP<const CrsMatrix> K, const CrsMatrix& M, double shift, const MultiVector& F,
                          MultiVector& Psi) {
  RCP<const CrsMatrix> A = shift > 0 ? RCP<const CrsMatrix>(addMatrices(1.0, *K, shift, M)) : K;
  Teuchos::ParameterList lp = linearSolverParameters();
  auto solver = makeLinearSolver(lp);
  solver->setMatrix(A);
  const LinearSolveStatus st = solver->solve(F, Psi);
  if (!st.converged) throw NumericalError("static correction: the static solve failed: " + st.message);
}

// The responses M-orthogonal to the modes (twice, for round-off) and to each other, M-normalised;
// what is left of a response already in the span is dropped.
std::vector<RCP<Vector>> orthogonalResponses(const CrsMatrix& M, const MultiVector& Phi, const MultiVector& Psi) {
  const size_t m = Phi.getNumVectors();
  std::vector<RCP<Vector>> kept;
  for (size_t j = 0; j < Psi.getNumVectors(); ++j) {
    RCP<Vector> x = rcp(new Vector(*Psi.getVector(j), Teuchos::Copy));
    const double before = massNorm(M, *x);
    if (!(before > 0)) continue;
    for (int pass = 0; pass < 2; ++pass) {
      Vector Mx(M.getRangeMap());
      M.apply(*x, Mx);
      for (size_t k = 0; k < m; ++k) x->update(-Phi.getVector(k)->dot(Mx), *Phi.getVector(k), 1.0);
      for (const auto& y : kept) x->update(-y->dot(Mx), *y, 1.0);
    }
    const double after = massNorm(M, *x);
    if (!(after > 1e-8 * before)) continue;
    x->scale(1.0 / after);
    kept.push_back(x);
  }
  return kept;
}

// Rayleigh-Ritz on the span of Q: Kr y = lambda Mr y (LAPACK dsygv). Returns the eigenvalues,
// ascending, and leaves the eigenvectors in Kr (n x n, column-major).
std::vector<double> rayleighRitz(const CrsMatrix& K, const CrsMatrix& M, const MultiVector& Q,
                                 std::vector<double>& Kr) {
  const size_t n = Q.getNumVectors();
  MultiVector KQ(Q.getMap(), n), MQ(Q.getMap(), n);
  K.apply(Q, KQ);
  M.apply(Q, MQ);
  Kr = transposeProduct(Q, KQ);
  std::vector<double> Mr = transposeProduct(Q, MQ);
  for (size_t i = 0; i < n; ++i)  // exact symmetry
    for (size_t j = 0; j < i; ++j) {
      Kr[j * n + i] = Kr[i * n + j] = 0.5 * (Kr[j * n + i] + Kr[i * n + j]);
      Mr[j * n + i] = Mr[i * n + j] = 0.5 * (Mr[j * n + i] + Mr[i * n + j]);
    }
  std::vector<double> w(n), work(std::max<size_t>(1, 3 * n));
  int info = 0;
  Teuchos::LAPACK<int, double>().SYGV(1, 'V', 'U', int(n), Kr.data(), int(n), Mr.data(), int(n), w.data(),
                                      work.data(), int(work.size()), &info);
  if (info != 0)
    throw NumericalError("static correction: the Rayleigh-Ritz eigenproblem failed (LAPACK dsygv info " +
                         std::to_string(info) + ")");
  return w;
}

}  // namespace

StaticCorrection enrichWithStaticModes(const ModalBasis& basis, Model& model,
                                       const std::vector<StaticLoad>& loads, double rigidFrequencyHz) {
  const CrsMatrix& K = *model.stiffness();
  const CrsMatrix& M = *model.mass();
  const MultiVector& Phi = *basis.vectors;
  const size_t m = Phi.getNumVectors();
  MultiVector F(model.map(), loads.size());
  fillUnitForces(model, loads, F);
  MultiVector Psi(model.map(), loads.size());
  solveStaticResponses(model.stiffness(), M, staticShift(basis, rigidFrequencyHz), F, Psi);
  const std::vector<RCP<Vector>> kept = orthogonalResponses(M, Phi, Psi);
  StaticCorrection out;
  out.added = static_cast<int>(kept.size());
  out.dropped = static_cast<int>(loads.size() - kept.size());
  const size_t n = m + kept.size();
  MultiVector Q(model.map(), n);
  for (size_t k = 0; k < m; ++k) Q.getVectorNonConst(k)->assign(*Phi.getVector(k));
  for (size_t k = 0; k < kept.size(); ++k) Q.getVectorNonConst(m + k)->assign(*kept[k]);
  std::vector<double> Kr;
  std::vector<double> w = rayleighRitz(K, M, Q, Kr);
  auto enriched = std::make_shared<ModalBasis>();
  enriched->name = basis.name + "+static";
  auto vectors = rcp(new MultiVector(model.map(), n));
  multiplyDense(Q, Kr, n, n, *vectors);  // dsygv left the eigenvectors in Kr
  for (double& l : w)
    if (std::abs(l) < 1e-9 * std::abs(w.back())) l = 0.0;  // rigid-body modes stay at 0
  enriched->eigenvalues = w;
  enriched->vectors = vectors;
  out.basis = enriched;
  return out;
}

}  // namespace choc
