#include "contact/ContactProjection.hpp"

#include <map>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"

namespace choc {

bool ContactProjection::applies(const ContactManager& contact) {
  if (!contact.method().hasMultipliers() || contact.method().stiffness() != 0.0 || contact.hasFriction() ||
      contact.numPairs() == 0)
    return false;
  for (int p = 0; p < contact.numPairs(); ++p)
    if (!contact.pair(p).hasObstacle) return true;
  return false;
}

// C's entries on this rank's rows and G = C^T C from the constraints' terms (the same on every
// rank), factored.
void ContactProjection::build() {
  const auto& cs = contact_.constraints();
  active_.clear();
  entries_.clear();
  std::map<GO, std::vector<std::pair<int, double>>> byDof;  // DOF -> (active constraint, coefficient)
  for (int s = 0; s < int(cs.size()); ++s) {
    if (!contact_.status()[s]) continue;
    const int k = int(active_.size());
    active_.push_back(s);
    std::map<GO, double> column;  // a DOF named twice in B_s sums
    for (const auto& [dof, coef] : cs[s].terms) column[dof] += coef;
    for (const auto& [dof, coef] : column) {
      byDof[dof].push_back({k, coef});
      const LO l = map_->getLocalElement(dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) entries_.push_back({l, k, coef});
    }
  }
  const int m = int(active_.size());
  cholesky_.assign(size_t(m) * size_t(m), 0.0);
  for (const auto& [dof, list] : byDof)
    for (const auto& [i, ci] : list)
      for (const auto& [j, cj] : list)
        if (i >= j) cholesky_[size_t(j) * m + i] += ci * cj;
  if (m == 0) return;
  std::vector<double> diag(m);
  for (int i = 0; i < m; ++i) diag[i] = cholesky_[size_t(i) * m + i];
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRF('L', m, cholesky_.data(), m, &info);
  // A pivot far below its diagonal: the constraint is (nearly) a combination of the others.
  for (int i = 0; info == 0 && i < m; ++i)
    if (!(cholesky_[size_t(i) * m + i] * cholesky_[size_t(i) * m + i] > 1e-12 * diag[i])) info = i + 1;
  if (info != 0)
    throw NumericalError("contact: the active constraints are linearly dependent at slave node " +
                         std::to_string(cs[active_[size_t(std::max(info, 1) - 1)]].geometry.slaveNode + 1) +
                         " (two slave nodes on one point, or a constraint along fixed components)");
}

std::vector<double> ContactProjection::transposeTimes(const double* x) const {
  std::vector<double> mine(active_.size(), 0.0), all(active_.size(), 0.0);
  for (const Entry& e : entries_) mine[e.k] += e.c * x[e.row];
  if (!mine.empty())
    Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, int(mine.size()), mine.data(), all.data());
  return all;
}

void ContactProjection::solveG(std::vector<double>& y) const {
  const int m = int(active_.size());
  if (m == 0) return;
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRS('L', m, 1, cholesky_.data(), m, y.data(), m, &info);
}

void ContactProjection::project(const MultiVector& X, MultiVector& Y) const {
  Y.assign(X);
  for (size_t j = 0; j < X.getNumVectors(); ++j) {
    auto x = X.getData(j);
    std::vector<double> y = transposeTimes(x.getRawPtr());
    solveG(y);
    auto out = Y.getDataNonConst(j);
    for (const Entry& e : entries_) out[e.row] -= e.c * y[e.k];
  }
}

void ContactProjection::rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) {
  std::vector<char> key = contact_.status();
  const int version = contact_.geometryVersion();
  const char* v = reinterpret_cast<const char*>(&version);
  key.insert(key.end(), v, v + sizeof version);
  if (!built_ || key != key_) {
    build();
    key_ = std::move(key);
    built_ = true;
  }
  const std::vector<double> g = contact_.gaps(u);
  d0Coef_.assign(active_.size(), 0.0);
  for (size_t k = 0; k < active_.size(); ++k) d0Coef_[k] = contact_.rowResidual(active_[k], g[active_[k]]) / scale();
  solveG(d0Coef_);
  Vector d0(map_);  // C G^-1 t
  {
    auto d = d0.getDataNonConst();
    for (const Entry& e : entries_) d[e.row] += e.c * d0Coef_[e.k];
  }
  if (residual_.is_null()) residual_ = rcp(new Vector(map_));
  residual_->assign(r);
  MultiVector rhs(map_, 1);  // -r - W d0
  W.apply(d0, rhs);
  rhs.update(-1.0, r, -1.0);
  project(rhs, b);
}

void ContactProjection::takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) const {
  MultiVector px(map_, 1);
  project(x, px);
  {
    auto d = du.getDataNonConst();
    auto p = px.getData(0);
    for (size_t i = 0; i < du.getLocalLength(); ++i) d[i] = p[i];
    for (const Entry& e : entries_) d[e.row] += e.c * d0Coef_[e.k];
  }
  Vector z(map_);  // W du + R
  W.apply(du, z);
  z.update(1.0, *residual_, 1.0);
  std::vector<double> y = transposeTimes(z.getData().getRawPtr());
  solveG(y);
  const double S = scale();
  const int nS = contact_.numConstraints(), rank = map_->getComm()->getRank();
  std::vector<double> mine(nS, 0.0), all(nS, 0.0);
  for (size_t k = 0; k < active_.size(); ++k)
    if (contact_.constraints()[active_[k]].owner == rank) mine[active_[k]] = y[k] / S;
  for (int s = 0; s < nS; ++s)  // an inactive node's pressure returns to 0
    if (!contact_.status()[s] && contact_.constraints()[s].owner == rank) mine[s] = -contact_.rowResidual(s, 0.0) / S;
  Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, nS, mine.data(), all.data());
  contact_.applyCorrection(all);
}

}  // namespace choc
