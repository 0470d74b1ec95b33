// Sparse matrix combinations used by solvers and integrators.
#pragma once
#include <Teuchos_Array.hpp>

#include "core/TpetraTypes.hpp"
#include "fem/DofMap.hpp"

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

// The largest over the nodes with all `dimension` spatial components free of the mean of the
// node's diagonal entries (the trace of its d x d diagonal block over d: unchanged by a rotation
// of the frame, unlike a single diagonal entry); the largest |diagonal entry| when no node has
// every component free. A is on the DOF map of `dofs`. Collective.
double largestNodalDiagonal(const CrsMatrix& A, const DofMap& dofs, int dimension);

// a A + b B (union of the two sparsity patterns), fill-completed on A's maps.
RCP<CrsMatrix> addMatrices(double a, const CrsMatrix& A, double b, const CrsMatrix& B);

}  // namespace choc
