#include "fem/SymmetricProduct.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

namespace {

// Every rank's answer: K is used symmetrically on all ranks or on none (a product is collective).
bool everywhere(const Comm& comm, bool mine) {
  int local = mine ? 1 : 0, global = 0;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, local, Teuchos::outArg(global));
  return global == 1;
}

}  // namespace

std::unique_ptr<SymmetricProduct> SymmetricProduct::build(const CrsMatrix& K) {
  const Comm& comm = *K.getComm();
  const auto rowMap = K.getRowMap(), colMap = K.getColMap();
  if (!everywhere(comm, K.isFillComplete() && rowMap->isSameAs(*K.getDomainMap()) &&
                            rowMap->isSameAs(*K.getRangeMap())))
    return nullptr;
  const auto A = K.getLocalMatrixHost();
  const size_t n = rowMap->getNodeNumElements();
  // Column index -> owned row index, or -1 for another rank's unknown.
  std::vector<LO> owned(colMap->getNodeNumElements(), -1);
  for (size_t c = 0; c < owned.size(); ++c) owned[c] = rowMap->getLocalElement(colMap->getGlobalElement(LO(c)));

  // Tpetra's column map lists the owned columns in the row map's order: with each row's entries
  // sorted by column, a row's owned columns are then ascending in owned index and need no sort.
  bool ordered = K.getCrsGraph()->isSorted();
  for (size_t c = 0, next = 0; c < owned.size() && ordered; ++c) {
    if (owned[c] < 0) continue;
    ordered = size_t(owned[c]) >= next;
    next = size_t(owned[c]) + 1;
  }

  std::unique_ptr<SymmetricProduct> p(new SymmetricProduct());
  p->diag_.assign(n, 0.0);
  p->upperRows_.assign(n + 1, 0);
  p->ghostRows_.assign(n + 1, 0);
  std::vector<double> rowScale(n, 0.0);
  size_t lower = 0;
  for (size_t i = 0; i < n; ++i) {
    for (auto k = A.graph.row_map(i); k < A.graph.row_map(i + 1); ++k) {
      const LO c = A.graph.entries(k), j = owned[c];
      rowScale[i] = std::max(rowScale[i], std::abs(A.values(k)));
      if (j < 0) ++p->ghostRows_[i + 1];
      else if (size_t(j) > i) ++p->upperRows_[i + 1];
      else if (size_t(j) < i) ++lower;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    p->upperRows_[i + 1] += p->upperRows_[i];
    p->ghostRows_[i + 1] += p->ghostRows_[i];
  }
  bool symmetric = lower == p->upperRows_[n];
  p->upperCols_.resize(p->upperRows_[n]);
  p->upperVals_.resize(p->upperRows_[n]);
  p->ghostCols_.resize(p->ghostRows_[n]);
  p->ghostVals_.resize(p->ghostRows_[n]);
  std::vector<std::pair<LO, double>> row;
  for (size_t i = 0; i < n && symmetric; ++i) {
    row.clear();
    size_t g = p->ghostRows_[i];
    for (auto k = A.graph.row_map(i); k < A.graph.row_map(i + 1); ++k) {
      const LO c = A.graph.entries(k), j = owned[c];
      if (j < 0) {
        p->ghostCols_[g] = c;
        p->ghostVals_[g++] = A.values(k);
      } else if (size_t(j) == i) {
        p->diag_[i] += A.values(k);
      } else if (size_t(j) > i) {
        row.emplace_back(j, A.values(k));
      }
    }
    if (!ordered) std::sort(row.begin(), row.end());  // ascending columns, for the check below
    size_t u = p->upperRows_[i];
    for (const auto& e : row) {
      if (u > p->upperRows_[i] && p->upperCols_[u - 1] == e.first) symmetric = false;  // duplicate
      p->upperCols_[u] = e.first;
      p->upperVals_[u++] = e.second;
    }
  }
  // Each lower entry a_ij (j < i) must be the stored a_ji within round-off of row i's scale. Row
  // i's lower entries come in ascending j, and the rows meeting a given j in ascending i, so
  // each upper row j is matched in order by a cursor: no search.
  std::vector<size_t> next(p->upperRows_.begin(), p->upperRows_.end() - 1);
  for (size_t i = 0; i < n && symmetric; ++i) {
    row.clear();
    for (auto k = A.graph.row_map(i); k < A.graph.row_map(i + 1); ++k) {
      const LO j = owned[A.graph.entries(k)];
      if (j >= 0 && size_t(j) < i) row.emplace_back(j, A.values(k));
    }
    if (!ordered) std::sort(row.begin(), row.end());
    for (size_t e = 0; e < row.size() && symmetric; ++e) {
      const size_t j = size_t(row[e].first), at = next[j]++;
      symmetric = at < p->upperRows_[j + 1] && p->upperCols_[at] == LO(i) &&
                  std::abs(p->upperVals_[at] - row[e].second) <= 1e-12 * rowScale[i];
    }
  }
  if (!everywhere(comm, symmetric)) return nullptr;
  p->importer_ = K.getGraph()->getImporter();
  if (!p->importer_.is_null()) p->column_ = rcp(new Vector(colMap));
  return p;
}

void SymmetricProduct::apply(const Vector& x, Vector& out) const {
  if (!importer_.is_null()) column_->doImport(x, *importer_, Tpetra::INSERT);
  auto xData = x.getData();
  auto yData = out.getDataNonConst();
  const double* xs = xData.getRawPtr();
  double* ys = yData.getRawPtr();
  const size_t n = diag_.size();
  // The diagonal and the other ranks' columns first: the upper triangle's transposed terms
  // then add into rows not yet reached.
  if (ghostCols_.empty()) {
    for (size_t i = 0; i < n; ++i) ys[i] = diag_[i] * xs[i];
  } else {
    auto cData = column_->getData();
    const double* xc = cData.getRawPtr();
    for (size_t i = 0; i < n; ++i) {
      double s = diag_[i] * xs[i];
      for (size_t k = ghostRows_[i]; k < ghostRows_[i + 1]; ++k) s += ghostVals_[k] * xc[ghostCols_[k]];
      ys[i] = s;
    }
  }
  const size_t* rows = upperRows_.data();
  const LO* cols = upperCols_.data();
  const double* vals = upperVals_.data();
  for (size_t i = 0; i < n; ++i) {
    const double xi = xs[i];
    double s0 = 0.0, s1 = 0.0;
    size_t k = rows[i];
    const size_t end = rows[i + 1];
    // Two running sums: one waits on each addition's latency.
    for (; k + 2 <= end; k += 2) {
      const LO c0 = cols[k], c1 = cols[k + 1];
      const double a0 = vals[k], a1 = vals[k + 1];
      s0 += a0 * xs[c0];
      s1 += a1 * xs[c1];
      ys[c0] += a0 * xi;
      ys[c1] += a1 * xi;
    }
    if (k < end) {
      s0 += vals[k] * xs[cols[k]];
      ys[cols[k]] += vals[k] * xi;
    }
    ys[i] += s0 + s1;
  }
}

}  // namespace choc
