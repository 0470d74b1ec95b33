// Sparse matrix combinations used by solvers and integrators.
#pragma once
#include <Teuchos_Array.hpp>

#include "core/TpetraTypes.hpp"

namespace choc {

// One row of a matrix in global indices, its buffers reused from row to row:
// read(A, g) leaves the entries of global row g (owned by this rank) in cols/vals[0, size).
struct RowCopy {
  Teuchos::Array<GO> cols;
  Teuchos::Array<double> vals;
  size_t size = 0;
  void read(const CrsMatrix& A, GO row);
};

// The largest |diagonal entry| of A over all ranks (collective).
double largestDiagonal(const CrsMatrix& A);

// a A + b B (union of the two sparsity patterns), fill-completed on A's maps.
RCP<CrsMatrix> addMatrices(double a, const CrsMatrix& A, double b, const CrsMatrix& B);

}  // namespace choc
