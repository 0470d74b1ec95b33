#include "fem/MatrixOps.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <TpetraExt_MatrixMatrix.hpp>

namespace choc {

RCP<CrsMatrix> addMatrices(double a, const CrsMatrix& A, double b, const CrsMatrix& B) {
  return Tpetra::MatrixMatrix::add(a, false, A, b, false, B);
}

}  // namespace choc
