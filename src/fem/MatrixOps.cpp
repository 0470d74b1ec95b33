#include "fem/MatrixOps.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>

namespace choc {

void RowCopy::read(const CrsMatrix& A, GO row) {
  const size_t n = A.getNumEntriesInGlobalRow(row);
  cols.resize(n);
  vals.resize(n);
  A.getGlobalRowCopy(row, cols(), vals(), size);
}

RCP<CrsMatrix> addMatrices(double a, const CrsMatrix& A, double b, const CrsMatrix& B) {
  return Tpetra::MatrixMatrix::add(a, false, A, b, false, B);
}

double largestDiagonal(const CrsMatrix& A) {
  Vector d(A.getRowMap());
  A.getLocalDiagCopy(d);
  return d.normInf();
}

double largestNodalDiagonal(const CrsMatrix& A, const DofMap& dofs, int dimension) {
  Vector d(A.getRowMap());
  A.getLocalDiagCopy(d);
  const auto values = d.getData();
  const auto& map = *A.getRowMap();
  double local = -1.0;  // no node with every component free
  for (int n = 0; n < dofs.numNodes(); ++n) {
    if (!dofs.ownsNode(n)) continue;
    double trace = 0.0;
    int free = 0;
    for (int c = 0; c < dimension; ++c) {
      const long long g = dofs.dof(n, c);
      if (g < 0) break;
      trace += values[map.getLocalElement(GO(g))];
      ++free;
    }
    if (free == dimension) local = std::max(local, std::abs(trace) / dimension);
  }
  double largest = -1.0;
  Teuchos::reduceAll<int, double>(*A.getComm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(largest));
  return largest >= 0.0 ? largest : d.normInf();
}

}  // namespace choc
