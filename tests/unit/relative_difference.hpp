// ||x - y|| / ||y|| of two single-column multivectors (all ranks), for the solver tests.
#pragma once
#include <vector>

#include <Teuchos_ArrayView.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/TpetraTypes.hpp"

namespace choc {

inline double relativeDifference(const MultiVector& x, const MultiVector& y) {
  MultiVector d(x, Teuchos::Copy);
  d.update(-1.0, y, 1.0);
  std::vector<double> nd(1), ny(1);
  d.norm2(Teuchos::ArrayView<double>(nd));
  y.norm2(Teuchos::ArrayView<double>(ny));
  return nd[0] / ny[0];
}

}  // namespace choc
