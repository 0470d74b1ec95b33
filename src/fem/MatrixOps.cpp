#include "fem/MatrixOps.hpp"

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

}  // namespace choc
