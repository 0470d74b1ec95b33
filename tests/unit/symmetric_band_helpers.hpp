// Shared by the symmetric product's tests (fem) and the symmetric Krylov operator's (solvers):
// a symmetric band matrix distributed in contiguous blocks, and a row-by-row comparison of a
// product with Tpetra's CRS product within round-off.
//
// The two products sum each row in different orders, so they agree within Higham's bound for
// two summation orders of sum_j a_ij x_j with n terms: 2 gamma_n sum_j |a_ij x_j|,
// gamma_n = n u / (1 - n u), u = 2^-53 (Accuracy and Stability of Numerical Algorithms, 4.4);
// Y = alpha A X + beta Y adds the rounding of the scaling and the sum: 4 u (|alpha| sum_j
// |a_ij x_j| + |beta y_i|).
#pragma once
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/TpetraTypes.hpp"

namespace choc {
namespace band {

inline long long sumOverRanks(long long v) {
  long long s = 0;
  MPI_Allreduce(&v, &s, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return s;
}

inline double probe(GO g) { return std::sin(0.37 * double(g) + 0.1) + 0.01 * double(g % 7); }

inline void noEdit(GO, std::vector<GO>&, std::vector<double>&) {}

// A symmetric band matrix of n rows and half-bandwidth w (a_ij = a_ji, a dominant diagonal),
// distributed in contiguous blocks: on 2 ranks the rows near the cut have columns on the other
// rank. `edit` may change entries before fillComplete (global row, column, value).
template <class Edit>
RCP<CrsMatrix> bandMatrix(GO n, int w, Edit edit) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(Tpetra::global_size_t(n), 0, comm));
  auto A = rcp(new CrsMatrix(map, size_t(2 * w + 2)));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO i = map->getGlobalElement(LO(l));
    std::vector<GO> cols;
    std::vector<double> vals;
    for (GO j = std::max<GO>(0, i - w); j <= std::min<GO>(n - 1, i + w); ++j) {
      const GO a = std::min(i, j), b = std::max(i, j);
      cols.push_back(j);
      vals.push_back(i == j ? 10.0 + 0.1 * double(i % 5) : -1.0 / double(1 + b - a) + 0.01 * std::sin(double(a + 3 * b)));
    }
    edit(i, cols, vals);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

// product(x, y) (y = alpha A x + beta y, y holding y0 on entry: NaN when beta = 0, which must
// not leak) against Tpetra's, row by row within the bound above; returns the rows outside it
// (all ranks).
template <class Product>
long long rowsOutsideRoundoff(const CrsMatrix& A, Product product, double alpha = 1.0, double beta = 0.0) {
  const auto map = A.getRowMap();
  Vector x(map), yCrs(map), y(map);
  const double y0 = beta == 0.0 ? std::numeric_limits<double>::quiet_NaN() : 0.75;
  for (size_t l = 0; l < x.getLocalLength(); ++l) x.replaceLocalValue(LO(l), probe(map->getGlobalElement(LO(l))));
  yCrs.putScalar(beta == 0.0 ? 0.0 : y0);
  A.apply(x, yCrs, Teuchos::NO_TRANS, alpha, beta);
  y.putScalar(y0);
  product(x, y);
  auto a = yCrs.getData(), b = y.getData();
  const double u = std::numeric_limits<double>::epsilon() / 2;
  long long bad = 0;
  for (size_t l = 0; l < x.getLocalLength(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    const size_t n = A.getNumEntriesInGlobalRow(g);
    CrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
    CrsMatrix::nonconst_values_host_view_type vals("vals", n);
    size_t got = 0;
    A.getGlobalRowCopy(g, cols, vals, got);
    double absSum = 0.0;
    for (size_t k = 0; k < got; ++k) absSum += std::fabs(vals[k] * probe(cols[k]));
    double bound = std::fabs(alpha) * 2.0 * (double(got) * u / (1.0 - double(got) * u)) * absSum;
    if (alpha != 1.0 || beta != 0.0) bound += 4.0 * u * (std::fabs(alpha) * absSum + (beta == 0.0 ? 0.0 : std::fabs(beta * y0)));
    if (!(std::fabs(a[l] - b[l]) <= bound) && ++bad <= 5)
      ADD_FAILURE() << "row " << g << ": product " << b[l] << ", CRS " << a[l] << ", bound " << bound;
  }
  return sumOverRanks(bad);
}

}  // namespace band
}  // namespace choc
