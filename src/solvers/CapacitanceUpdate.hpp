// An exact solve of a matrix A that differs from a factored matrix P in a few rows, with P's
// factorisation and a small dense matrix (the Sherman-Morrison-Woodbury capacitance form):
//   A = P + Q_r E Q_c^T,   E = (A - P) on the changed rows r and the columns c they touch,
//   W = P^-1 Q_r (one column per changed row, kept while P is),
//   A x = b  <=>  (I + W_c E) x_c = (P^-1 b)_c,   x = P^-1 b - W (E x_c),
// where W_c is W's rows c: one solve with P per right-hand side, however many rows changed.
// Contact and friction change only the rows of the nodes in contact (their multipliers and
// couplings) while the structure's effective stiffness stays what P holds, so a run keeps one
// factorisation while the contact zone's columns fit (see maxColumns in prepare()).
//
// The columns are computed in blocks (the rows new to each matrix) and kept until P is
// refactored, at most maxColumns of them: a matrix that would need more is refactored. A
// restarted run that refactors the same P computes the same blocks again (restart bit for bit),
// and the dense matrix is assembled in the order of the global indices.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

class CapacitanceUpdate {
 public:
  // x = P^-1 b (collective): the factorisation's solve; "" or its failure's message.
  using FactoredSolve = std::function<std::string(const MultiVector&, MultiVector&)>;

  // P was factored: keeps its values and forgets the columns of the previous P.
  void reset(const RCP<const CrsMatrix>& P);
  // Makes ready to solve with A (collective). False (with an empty failure) when A is not
  // P's graph, its changed rows need more than maxColumns columns in all or more than maxNew
  // new ones, or the dense matrix is singular: the caller solves otherwise. failure: a solve
  // that failed. computed: the new columns computed.
  bool prepare(const CrsMatrix& A, size_t maxColumns, size_t maxNew, const FactoredSolve& solveP,
               std::string& failure, size_t& computed);
  // x = A^-1 b for the prepared A (collective): one solve with P.
  std::string solve(const MultiVector& b, MultiVector& x, const FactoredSolve& solveP) const;
  // The blocks of columns computed since reset(), in order (each: its size, then its rows), and
  // the same blocks computed again after reset() with the same P (collective): a restart.
  std::vector<long long> blocks() const;
  std::string restoreBlocks(const RCP<const Map>& map, const std::vector<long long>& state, size_t from,
                            const FactoredSolve& solveP);
  // The changed rows and the columns they touch, of the prepared A.
  size_t rows() const { return rows_.size(); }
  size_t columns() const { return cols_.size(); }

 private:
  struct Change {
    GO row, col;
    double value;
  };
  bool sameGraph(const CrsMatrix& A) const;
  std::vector<Change> changes(const CrsMatrix& A) const;
  std::string computeColumns(const RCP<const Map>& map, const std::vector<GO>& rows, const FactoredSolve& solveP);
  std::vector<double> rowsOf(const std::vector<const Vector*>& vs, const std::vector<GO>& at) const;
  bool factorDense(const std::vector<Change>& E);

  RCP<const CrsMatrix> P_;       // the factored matrix object (may be refilled: values_ holds P)
  std::vector<double> values_;   // P's local values, in the graph's order
  std::map<GO, RCP<Vector>> W_;  // P^-1 e_row, by global row
  std::vector<std::vector<GO>> blocks_;  // W's rows as computed, block by block
  std::vector<GO> rows_, cols_;  // r and c of the prepared A, ascending
  std::vector<double> EbyCol_;   // E (|r| x |c|, column-major)
  std::vector<double> M_;        // LU of I + W_c E (|c| x |c|, column-major)
  std::vector<int> pivots_;
};

}  // namespace choc
