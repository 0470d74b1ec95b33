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
  std::unique_ptr<SymmetricProduct> p(new SymmetricProduct());
  // Column index -> owned row index, or -1 for another rank's unknown.
  p->owned_.assign(colMap->getNodeNumElements(), -1);
  for (size_t c = 0; c < p->owned_.size(); ++c)
    p->owned_[c] = rowMap->getLocalElement(colMap->getGlobalElement(LO(c)));

  // Tpetra's usual layout: column c < n is owned row c and the other ranks' columns come after
  // them. With each row sorted, a row is then [lower | diagonal | upper | other ranks'], and
  // fill() copies its upper and ghost parts in blocks; any other layout sorts each row.
  p->identity_ = K.getCrsGraph()->isSorted();
  for (size_t c = 0; c < p->owned_.size() && p->identity_; ++c)
    p->identity_ = c < n ? p->owned_[c] == LO(c) : p->owned_[c] < 0;

  p->diag_.assign(n, 0.0);
  p->upperRows_.assign(n + 1, 0);
  p->ghostRows_.assign(n + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    for (auto k = A.graph.row_map(i); k < A.graph.row_map(i + 1); ++k) {
      const LO j = p->owned_[A.graph.entries(k)];
      if (j < 0) ++p->ghostRows_[i + 1];
      else if (size_t(j) > i) ++p->upperRows_[i + 1];
    }
  }
  for (size_t i = 0; i < n; ++i) {
    p->upperRows_[i + 1] += p->upperRows_[i];
    p->ghostRows_[i + 1] += p->ghostRows_[i];
  }
  p->upperCols_.resize(p->upperRows_[n]);
  p->upperVals_.resize(p->upperRows_[n]);
  p->ghostCols_.resize(p->ghostRows_[n]);
  p->ghostVals_.resize(p->ghostRows_[n]);
  p->entries_ = A.graph.entries.extent(0);
  const bool symmetric = p->fill(K, true);
  if (!everywhere(comm, symmetric)) return nullptr;
  p->colMap_ = colMap;
  p->importer_ = K.getGraph()->getImporter();
  if (!p->importer_.is_null()) p->column_ = rcp(new Vector(colMap));
  return p;
}

bool SymmetricProduct::refill(const CrsMatrix& K) {
  const auto A = K.getLocalMatrixHost();
  // The local column indices must name the same unknowns as when built (isSameAs is collective,
  // as refill() is; the same map object answers at once).
  const bool sameColumns = K.isFillComplete() && K.getColMap()->isSameAs(*colMap_);
  const bool same = sameColumns && A.graph.entries.extent(0) == entries_ &&
                    A.numRows() == LO(diag_.size()) && size_t(A.numCols()) == owned_.size() &&
                    K.getGraph()->getImporter().get() == importer_.get();
  return everywhere(*K.getComm(), same && fill(K, false));
}

// a_ij (j < i) against the stored a_ji: the next entry of upper row j must be column i, its
// value within round-off of row i's largest entry (`scale`).
bool SymmetricProduct::matchesTranspose(size_t i, size_t j, double a, double scale, std::vector<size_t>& next) const {
  const size_t at = next[j]++;
  return at < upperRows_[j + 1] && upperCols_[at] == LO(i) && std::abs(upperVals_[at] - a) <= 1e-12 * scale;
}

// Row i's entries in order: the other ranks' columns to the ghost CSR, the diagonal, the upper
// entries (ascending column), and each lower entry a_ij (j < i) checked against the stored a_ji
// within round-off of row i's largest entry. Row j < i is stored before row i is reached; row
// i's lower entries come in ascending j and the rows meeting a given j in ascending i, so each
// upper row j is matched in order by a cursor: no search; at the end every cursor must have
// reached its row's end (an upper entry without a lower partner). `structure`: write the column
// indices (build); else check them (refill: a graph that changed is not K's).
bool SymmetricProduct::fill(const CrsMatrix& K, bool structure) {
  const auto A = K.getLocalMatrixHost();
  const size_t n = diag_.size();
  std::vector<size_t> next(upperRows_.begin(), upperRows_.end() - 1);
  if (identity_) return fillRows(A, structure, next);
  size_t g = 0;
  std::vector<std::pair<LO, double>> upper, lower;  // a row's owned entries, to sort
  for (size_t i = 0; i < n; ++i) {
    const auto begin = A.graph.row_map(i), end = A.graph.row_map(i + 1);
    double scale = 0.0, d = 0.0;
    for (auto k = begin; k < end; ++k) scale = std::max(scale, std::abs(A.values(k)));
    upper.clear();
    lower.clear();
    for (auto k = begin; k < end; ++k) {
      const LO c = A.graph.entries(k), j = owned_[c];
      const double a = A.values(k);
      if (j < 0) {
        if (g == ghostRows_[i + 1]) return false;
        if (structure) ghostCols_[g] = c;
        else if (ghostCols_[g] != c) return false;
        ghostVals_[g++] = a;
      } else if (size_t(j) == i) {
        d += a;
      } else {
        (size_t(j) > i ? upper : lower).emplace_back(j, a);
      }
    }
    diag_[i] = d;
    std::sort(upper.begin(), upper.end());
    std::sort(lower.begin(), lower.end());
    size_t u = upperRows_[i];
    for (const auto& e : upper) {
      if (u == upperRows_[i + 1] || (u > upperRows_[i] && upperCols_[u - 1] >= e.first)) return false;  // duplicate
      if (structure) upperCols_[u] = e.first;
      else if (upperCols_[u] != e.first) return false;
      upperVals_[u++] = e.second;
    }
    for (const auto& e : lower)
      if (!matchesTranspose(i, size_t(e.first), e.second, scale, next)) return false;
    if (g != ghostRows_[i + 1] || u != upperRows_[i + 1]) return false;
  }
  for (size_t j = 0; j < n; ++j)  // every upper entry met its transposed partner
    if (next[j] != upperRows_[j + 1]) return false;
  return true;
}

// fill() for the usual layout (identity_): each sorted row is [lower | diagonal | upper | other
// ranks'] in local columns, so the lower entries are checked in one loop and the upper and
// ghost parts are copied (their columns written, or compared on a refill) as blocks: a refill
// of the 300k scene's effective matrix took 100 ms entry by entry.
template <class LocalMatrix>
bool SymmetricProduct::fillRows(const LocalMatrix& A, bool structure, std::vector<size_t>& next) {
  const size_t n = diag_.size();
  const auto& cols = A.graph.entries;
  const auto& vals = A.values;
  size_t g = 0;
  for (size_t i = 0; i < n; ++i) {
    size_t k = A.graph.row_map(i);
    const size_t end = A.graph.row_map(i + 1);
    double scale = 0.0;
    for (size_t e = k; e < end; ++e) scale = std::max(scale, std::abs(vals(e)));
    for (; k < end && size_t(cols(k)) < i; ++k)  // lower: the stored a_ji
      if (!matchesTranspose(i, size_t(cols(k)), vals(k), scale, next)) return false;
    double d = 0.0;
    for (; k < end && size_t(cols(k)) == i; ++k) d += vals(k);
    diag_[i] = d;
    const size_t u = upperRows_[i], nu = upperRows_[i + 1] - u, ng = ghostRows_[i + 1] - g;
    if (end - k != nu + ng) return false;
    for (size_t e = 0; e < nu; ++e) {
      const LO c = cols(k + e);
      if (structure) upperCols_[u + e] = c;
      else if (upperCols_[u + e] != c) return false;
      upperVals_[u + e] = vals(k + e);
    }
    if (nu > 0 && (size_t(cols(k)) <= i || size_t(cols(k + nu - 1)) >= n)) return false;
    k += nu;
    for (size_t e = 0; e < ng; ++e, ++g) {
      const LO c = cols(k + e);
      if (structure) ghostCols_[g] = c;
      else if (ghostCols_[g] != c) return false;
      ghostVals_[g] = vals(k + e);
    }
    if (ng > 0 && size_t(cols(k)) < n) return false;
  }
  for (size_t j = 0; j < n; ++j)  // every upper entry met its transposed partner
    if (next[j] != upperRows_[j + 1]) return false;
  return true;
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
