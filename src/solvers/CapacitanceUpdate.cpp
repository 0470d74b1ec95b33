#include "solvers/CapacitanceUpdate.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

namespace {

// The smallest reciprocal condition number (1-norm) of I + W_c E accepted: below it the dense
// solve would lose more digits than a refactorisation costs time.
constexpr double kSmallestRcond = 1e-12;

size_t indexOf(const std::vector<GO>& sorted, GO g) {
  return size_t(std::lower_bound(sorted.begin(), sorted.end(), g) - sorted.begin());
}

}  // namespace

void CapacitanceUpdate::reset(const RCP<const CrsMatrix>& P) {
  P_ = P;
  const auto L = P->getLocalMatrixHost();
  values_.assign(L.values.data(), L.values.data() + L.values.extent(0));
  W_.clear();
  blocks_.clear();
  rows_.clear();
  cols_.clear();
}

// A has P's structure on this rank: the same graph object (a matrix refilled in place), or the
// same rows, columns and local pattern.
bool CapacitanceUpdate::sameGraph(const CrsMatrix& A) const {
  if (P_.is_null()) return false;
  const auto a = A.getLocalMatrixHost().graph, p = P_->getLocalMatrixHost().graph;
  if (a.entries.extent(0) != values_.size() || p.entries.extent(0) != values_.size()) return false;
  if (A.getCrsGraph().get() == P_->getCrsGraph().get()) return true;
  if (!A.getRowMap()->isSameAs(*P_->getRowMap()) || !A.getColMap()->isSameAs(*P_->getColMap()) ||
      a.row_map.extent(0) != p.row_map.extent(0))
    return false;
  for (size_t i = 0; i < a.row_map.extent(0); ++i)
    if (a.row_map(i) != p.row_map(i)) return false;
  for (size_t k = 0; k < a.entries.extent(0); ++k)
    if (a.entries(k) != p.entries(k)) return false;
  return true;
}

// A's entries that differ from P's, every rank's, on every rank, ordered by row and column.
std::vector<CapacitanceUpdate::Change> CapacitanceUpdate::changes(const CrsMatrix& A) const {
  const auto L = A.getLocalMatrixHost();
  const auto rowMap = A.getRowMap(), colMap = A.getColMap();
  std::vector<double> mine;  // (row, col, value) triples
  for (size_t i = 0; i + 1 < L.graph.row_map.extent(0); ++i)
    for (size_t k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k)
      if (L.values(k) != values_[k]) {
        mine.push_back(double(rowMap->getGlobalElement(LO(i))));
        mine.push_back(double(colMap->getGlobalElement(L.graph.entries(k))));
        mine.push_back(L.values(k) - values_[k]);
      }
  // Every rank's triples, padded to the longest (global indices are below 2^53: exact).
  const Comm& comm = *A.getComm();
  int count = int(mine.size()), longest = 0;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MAX, count, Teuchos::outArg(longest));
  mine.resize(size_t(longest) + 1, -1.0);
  mine.back() = count;
  std::vector<double> all(mine.size() * size_t(comm.getSize()));
  Teuchos::gatherAll<int, double>(comm, int(mine.size()), mine.data(), int(all.size()), all.data());
  std::vector<Change> E;
  for (int p = 0; p < comm.getSize(); ++p) {
    const double* t = all.data() + size_t(p) * mine.size();
    for (int k = 0; k + 2 < int(t[longest]); k += 3) E.push_back({GO(t[k]), GO(t[k + 1]), t[k + 2]});
  }
  std::sort(E.begin(), E.end(), [](const Change& a, const Change& b) {
    return a.row != b.row ? a.row < b.row : a.col < b.col;
  });
  return E;
}

bool CapacitanceUpdate::prepare(const CrsMatrix& A, size_t maxColumns, size_t maxNew, const FactoredSolve& solveP,
                                std::string& failure, size_t& computed) {
  failure.clear();
  computed = 0;
  rows_.clear();
  cols_.clear();
  int local = sameGraph(A) ? 1 : 0, everywhere = 0;
  Teuchos::reduceAll<int, int>(*A.getComm(), Teuchos::REDUCE_MIN, local, Teuchos::outArg(everywhere));
  if (!everywhere) return false;
  const std::vector<Change> E = changes(A);
  for (const Change& e : E) {
    rows_.push_back(e.row);
    cols_.push_back(e.col);
  }
  for (std::vector<GO>* s : {&rows_, &cols_}) {
    std::sort(s->begin(), s->end());
    s->erase(std::unique(s->begin(), s->end()), s->end());
  }
  std::vector<GO> missing;
  for (GO row : rows_)
    if (!W_.count(row)) missing.push_back(row);
  if (cols_.size() > maxColumns || W_.size() + missing.size() > maxColumns || missing.size() > maxNew) return false;
  failure = computeColumns(A.getRowMap(), missing, solveP);
  if (!failure.empty()) return false;
  computed = missing.size();
  return factorDense(E);
}

std::vector<long long> CapacitanceUpdate::blocks() const {
  std::vector<long long> out;
  for (const std::vector<GO>& b : blocks_) {
    out.push_back((long long)b.size());
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

std::string CapacitanceUpdate::restoreBlocks(const RCP<const Map>& map, const std::vector<long long>& s, size_t from,
                                             const FactoredSolve& solveP) {
  for (size_t k = from; k < s.size(); k += size_t(s[k]) + 1) {
    if (s[k] < 0 || k + 1 + size_t(s[k]) > s.size()) return "a checkpoint's kept columns are truncated";
    const std::vector<GO> block(s.begin() + k + 1, s.begin() + k + 1 + s[k]);
    if (std::string f = computeColumns(map, block, solveP); !f.empty()) return f;
  }
  return "";
}

// The columns of W at `rows`, in one block of right-hand sides (MUMPS reads its factors once per
// block of columns). A column's round-off may depend on the block it was computed in: blocks_
// records them so that a restarted run computes the same blocks.
std::string CapacitanceUpdate::computeColumns(const RCP<const Map>& map, const std::vector<GO>& rows,
                                              const FactoredSolve& solveP) {
  if (rows.empty()) return "";
  MultiVector E(map, rows.size()), X(map, rows.size());
  for (size_t j = 0; j < rows.size(); ++j) {
    const LO i = map->getLocalElement(rows[j]);
    if (i != Teuchos::OrdinalTraits<LO>::invalid()) E.replaceLocalValue(i, j, 1.0);
  }
  if (std::string f = solveP(E, X); !f.empty()) return f;
  for (size_t j = 0; j < rows.size(); ++j) W_[rows[j]] = rcp(new Vector(*X.getVector(j), Teuchos::Copy));
  blocks_.push_back(rows);
  return "";
}

// The entries of each vector of vs at the global indices `at`, on every rank, vector after
// vector (the owners' values, in one reduction; the sums are exact).
std::vector<double> CapacitanceUpdate::rowsOf(const std::vector<const Vector*>& vs, const std::vector<GO>& at) const {
  std::vector<double> mine(vs.size() * at.size(), 0.0), all(mine.size(), 0.0);
  if (mine.empty()) return all;
  const auto map = vs.front()->getMap();
  for (size_t j = 0; j < vs.size(); ++j) {
    const auto data = vs[j]->getData();
    for (size_t q = 0; q < at.size(); ++q) {
      const LO i = map->getLocalElement(at[q]);
      if (i != Teuchos::OrdinalTraits<LO>::invalid()) mine[j * at.size() + q] = data[i];
    }
  }
  Teuchos::reduceAll<int, double>(*map->getComm(), Teuchos::REDUCE_SUM, int(mine.size()), mine.data(), all.data());
  return all;
}

// M = I + W_c E, factored by LU with partial pivoting; false when (nearly) singular.
bool CapacitanceUpdate::factorDense(const std::vector<Change>& E) {
  const size_t nr = rows_.size(), nc = cols_.size();
  EbyCol_.assign(nr * nc, 0.0);
  for (const Change& e : E) EbyCol_[indexOf(cols_, e.col) * nr + indexOf(rows_, e.row)] += e.value;
  M_.assign(nc * nc, 0.0);
  for (size_t q = 0; q < nc; ++q) M_[q * nc + q] = 1.0;
  std::vector<const Vector*> W;
  for (GO row : rows_) W.push_back(W_.at(row).get());
  const std::vector<double> Wc = rowsOf(W, cols_);  // W_c by columns (|c| x |r|)
  for (size_t j = 0; j < nr; ++j)
    for (size_t q = 0; q < nc; ++q) {
      const double e = EbyCol_[q * nr + j];
      if (e != 0.0)
        for (size_t i = 0; i < nc; ++i) M_[q * nc + i] += Wc[j * nc + i] * e;
    }
  if (nc == 0) return true;
  Teuchos::LAPACK<int, double> lapack;
  const int n = int(nc);
  double norm1 = 0.0;
  for (size_t q = 0; q < nc; ++q) {
    double s = 0.0;
    for (size_t i = 0; i < nc; ++i) s += std::fabs(M_[q * nc + i]);
    norm1 = std::max(norm1, s);
  }
  pivots_.assign(nc, 0);
  int info = 0;
  lapack.GETRF(n, n, M_.data(), n, pivots_.data(), &info);
  if (info != 0) return false;
  double rcond = 0.0;
  std::vector<double> work(4 * nc);
  std::vector<int> iwork(nc);
  lapack.GECON('1', n, M_.data(), n, norm1, &rcond, work.data(), iwork.data(), &info);
  return info == 0 && std::isfinite(rcond) && rcond >= kSmallestRcond;
}

std::string CapacitanceUpdate::solve(const MultiVector& b, MultiVector& x, const FactoredSolve& solveP) const {
  if (std::string f = solveP(b, x); !f.empty()) return f;  // x = P^-1 b
  const size_t nr = rows_.size(), nc = cols_.size();
  if (nc == 0) return "";
  Teuchos::LAPACK<int, double> lapack;
  for (size_t j = 0; j < x.getNumVectors(); ++j) {
    auto xj = x.getVectorNonConst(j);
    std::vector<double> xc = rowsOf({xj.get()}, cols_);
    int info = 0;
    lapack.GETRS('N', int(nc), 1, M_.data(), int(nc), pivots_.data(), xc.data(), int(nc), &info);
    if (info != 0) return "the capacitance form's dense solve failed (LAPACK dgetrs info " + std::to_string(info) + ")";
    for (size_t k = 0; k < nr; ++k) {
      double y = 0.0;  // (E x_c)_k
      for (size_t q = 0; q < nc; ++q) y += EbyCol_[q * nr + k] * xc[q];
      if (y != 0.0) xj->update(-y, *W_.at(rows_[k]), 1.0);
    }
  }
  return "";
}

}  // namespace choc
