#include "contact/ContactProjection.hpp"

#include <algorithm>
#include <cstdlib>
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

namespace {

// 300 by measurement (docs/performance/direct-packages.md, "Many active constraints"); test
// hook: CHOC_TEST_SPARSE_GRAM_FROM=N (the tests of the sparse path on small scenes).
int initialSparseFrom() {
  const char* e = std::getenv("CHOC_TEST_SPARSE_GRAM_FROM");
  return e && *e ? std::max(0, std::atoi(e)) : 300;
}

}  // namespace

int ContactProjection::sparseFrom = initialSparseFrom();

// C's entries on this rank's rows and G = C^T C from the constraints' terms (the same on every
// rank), factored.
void ContactProjection::build() {
  const auto& cs = contact_.constraints();
  active_.clear();
  entries_.clear();
  ConstraintsByDof byDof;
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
  sparse_ = m >= sparseFrom;
  if (sparse_)
    factorSparseGram(byDof);
  else
    factorDenseGram(byDof);
}

void ContactProjection::throwDependent(int k) const {
  const auto& cs = contact_.constraints();
  throw NumericalError("contact: the active constraints are linearly dependent" +
                       (k >= 0 ? " at slave node " + std::to_string(cs[active_[size_t(k)]].geometry.slaveNode + 1) : "") +
                       " (two slave nodes on one point, or a constraint along fixed components)");
}

void ContactProjection::factorSparseGram(const ConstraintsByDof& byDof) {
  gramEntries_.clear();
  cholesky_.clear(), gram_.clear();
  for (const auto& [dof, list] : byDof)
    for (const auto& [i, ci] : list)
      for (const auto& [j, cj] : list) gramEntries_.push_back({i, j, ci * cj});
  if (!sparseG_.factor(int(active_.size()), gramEntries_)) throwDependent(-1);
}

void ContactProjection::factorDenseGram(const ConstraintsByDof& byDof) {
  const int m = int(active_.size());
  cholesky_.assign(size_t(m) * size_t(m), 0.0);
  for (const auto& [dof, list] : byDof)
    for (const auto& [i, ci] : list)
      for (const auto& [j, cj] : list)
        if (i >= j) cholesky_[size_t(j) * m + i] += ci * cj;
  if (m == 0) return;
  gram_ = cholesky_;
  std::vector<double> diag(m);
  for (int i = 0; i < m; ++i) diag[i] = cholesky_[size_t(i) * m + i];
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRF('L', m, cholesky_.data(), m, &info);
  // A pivot far below its diagonal: the constraint is (nearly) a combination of the others.
  for (int i = 0; info == 0 && i < m; ++i)
    if (!(cholesky_[size_t(i) * m + i] * cholesky_[size_t(i) * m + i] > 1e-12 * diag[i])) info = i + 1;
  if (info != 0) throwDependent(std::max(info, 1) - 1);
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
  if (sparse_) return sparseG_.solve(y);
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POTRS('L', m, 1, cholesky_.data(), m, y.data(), m, &info);
}

// Y = X - C z (and - (V - C) z when oblique) with z = G^-1 C^T X, or (C^T V)^-1 C^T X.
void ContactProjection::subtractColumns(const MultiVector& X, MultiVector& Y, bool oblique) const {
  Y.assign(X);
  for (size_t j = 0; j < X.getNumVectors(); ++j) {
    auto x = X.getData(j);
    std::vector<double> y = transposeTimes(x.getRawPtr());
    if (oblique) solveCtV(y);
    else solveG(y);
    auto out = Y.getDataNonConst(j);
    for (const Entry& e : entries_) out[e.row] -= e.c * y[e.k];
    if (oblique)
      for (const Entry& e : frictionEntries_) out[e.row] -= e.c * y[e.k];
  }
}

void ContactProjection::project(const MultiVector& X, MultiVector& Y) const { subtractColumns(X, Y, false); }

void ContactProjection::setMultiplierColumns(std::vector<MatrixEntry> entries, GO multiplierBase) {
  multiplierColumns_ = std::move(entries);
  multiplierBase_ = multiplierBase;
  built_ = false;  // V follows each fill
}

std::vector<char> ContactProjection::key() const {
  std::vector<char> key = contact_.status();
  const int version = contact_.geometryVersion();
  const char* v = reinterpret_cast<const char*>(&version);
  key.insert(key.end(), v, v + sizeof version);
  return key;
}

// V - C from the friction entries in the active constraints' columns, C^T V summed over the
// ranks and LU-factored; V = C (no sliding node) leaves P_L = P.
void ContactProjection::buildOblique() {
  frictionEntries_.clear();
  const int m = int(active_.size());
  std::vector<int> activeIndex(contact_.numConstraints(), -1);
  for (int k = 0; k < m; ++k) activeIndex[active_[k]] = k;
  const double S = scale();
  for (const MatrixEntry& e : multiplierColumns_) {
    const int k = activeIndex[size_t(e.col - multiplierBase_)];
    const LO l = map_->getLocalElement(e.row);
    if (k >= 0 && l != Teuchos::OrdinalTraits<LO>::invalid() && e.value != 0.0)
      frictionEntries_.push_back({l, k, -e.value / S});
  }
  int any = frictionEntries_.empty() ? 0 : 1, anyAll = 0;
  Teuchos::reduceAll<int, int>(*map_->getComm(), Teuchos::REDUCE_MAX, any, Teuchos::outArg(anyAll));
  oblique_ = anyAll != 0;
  if (!oblique_) return;
  if (sparse_) {  // C^T V = G + C^T (V - C)
    std::vector<ReplicatedSparseLU::Entry> ctv = frictionCoupling();
    ctv.insert(ctv.end(), gramEntries_.begin(), gramEntries_.end());
    if (!sparseCtV_.factor(m, ctv))
      throw NumericalError("contact: the friction of the sliding nodes makes the projected constraints singular "
                           "(C^T V, sparse)");
    return;
  }
  // C^T V = G + C^T (V - C): the second term from this rank's rows, summed.
  std::vector<double> mine(size_t(m) * m, 0.0);
  for (const auto& [ij, v] : localFrictionCoupling()) mine[size_t(ij.second) * m + ij.first] += v;
  ctvLU_.assign(size_t(m) * m, 0.0);
  Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, m * m, mine.data(), ctvLU_.data());
  for (int j = 0; j < m; ++j)  // + G (its lower triangle kept)
    for (int i = 0; i < m; ++i) ctvLU_[size_t(j) * m + i] += gram_[size_t(std::min(i, j)) * m + std::max(i, j)];
  ctvPivots_.assign(size_t(m), 0);
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.GETRF(m, m, ctvLU_.data(), m, ctvPivots_.data(), &info);
  if (info != 0)
    throw NumericalError("contact: the friction of the sliding nodes makes the projected constraints singular "
                         "(C^T V, pivot " + std::to_string(info) + ")");
}

std::map<std::pair<int, int>, double> ContactProjection::localFrictionCoupling() const {
  std::vector<std::vector<std::pair<int, double>>> cByRow(map_->getNodeNumElements());
  for (const Entry& e : entries_) cByRow[size_t(e.row)].push_back({e.k, e.c});
  std::map<std::pair<int, int>, double> mine;
  for (const Entry& f : frictionEntries_)
    for (const auto& [k, c] : cByRow[size_t(f.row)]) mine[{k, f.k}] += c * f.c;
  return mine;
}

std::vector<ReplicatedSparseLU::Entry> ContactProjection::frictionCoupling() const {
  // Every rank's entries to every rank: the counts, then the (row, col) pairs and the values.
  std::vector<int> ij;
  std::vector<double> values;
  for (const auto& [key, v] : localFrictionCoupling()) ij.push_back(key.first), ij.push_back(key.second), values.push_back(v);
  const Comm& comm = *map_->getComm();
  const int ranks = comm.getSize(), count = int(values.size());
  std::vector<int> counts(size_t(ranks), 0);
  Teuchos::gatherAll<int, int>(comm, 1, &count, ranks, counts.data());
  int total = 0;
  for (int c : counts) total += c;
  std::vector<double> allValues(size_t(total), 0.0);
  std::vector<int> allIJ(size_t(2 * total), 0);
  int offset = 0;
  for (int r = 0; r < comm.getRank(); ++r) offset += counts[size_t(r)];
  // Each rank writes its slice, the others zeros: a sum is the concatenation.
  std::copy(values.begin(), values.end(), allValues.begin() + offset);
  std::copy(ij.begin(), ij.end(), allIJ.begin() + 2 * offset);
  std::vector<double> sumValues(allValues.size(), 0.0);
  std::vector<int> sumIJ(allIJ.size(), 0);
  if (total > 0) {
    Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_SUM, total, allValues.data(), sumValues.data());
    Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_SUM, 2 * total, allIJ.data(), sumIJ.data());
  }
  std::vector<ReplicatedSparseLU::Entry> out;
  for (int t = 0; t < total; ++t) out.push_back({sumIJ[size_t(2 * t)], sumIJ[size_t(2 * t + 1)], sumValues[size_t(t)]});
  return out;
}

void ContactProjection::solveCtV(std::vector<double>& y) const {
  const int m = int(active_.size());
  if (m == 0) return;
  if (sparse_) return sparseCtV_.solve(y);
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.GETRS('N', m, 1, ctvLU_.data(), m, ctvPivots_.data(), y.data(), m, &info);
}

void ContactProjection::projectRows(const MultiVector& X, MultiVector& Y) const { subtractColumns(X, Y, oblique_); }

void ContactProjection::rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) {
  std::vector<char> k = key();
  if (!built_ || k != key_) {
    built_ = false;  // a factorisation that throws leaves nothing to reuse
    build();
    buildOblique();
    key_ = std::move(k);
    built_ = true;
  }
  const std::vector<double> g = contact_.gaps(u);
  d0Coef_.assign(active_.size(), 0.0);
  for (size_t k = 0; k < active_.size(); ++k) d0Coef_[k] = contact_.activeSet().rowResidual(active_[k], g[active_[k]]) / scale();
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
  projectRows(rhs, b);
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
  if (oblique_) solveCtV(y);  // V dlambda = z in range(C): (C^T V) dlambda = C^T z
  else solveG(y);
  const double S = scale();
  const int nS = contact_.numConstraints(), rank = map_->getComm()->getRank();
  std::vector<double> mine(nS, 0.0), all(nS, 0.0);
  for (size_t k = 0; k < active_.size(); ++k)
    if (contact_.constraints()[active_[k]].owner == rank) mine[active_[k]] = y[k] / S;
  for (int s = 0; s < nS; ++s)  // an inactive node's pressure returns to 0
    if (!contact_.status()[s] && contact_.constraints()[s].owner == rank) mine[s] = -contact_.activeSet().rowResidual(s, 0.0) / S;
  Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, nS, mine.data(), all.data());
  contact_.activeSet().applyCorrection(all);
}

}  // namespace choc
