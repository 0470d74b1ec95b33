#include "solvers/DenseEigenSolver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <mpi.h>
#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"

namespace choc {

namespace {

// The whole matrix, column-major n x n, on rank 0 (empty elsewhere).
std::vector<double> denseOnRoot(const CrsMatrix& A, long long n) {
  const int rank = A.getComm()->getRank(), size = A.getComm()->getSize();
  std::vector<double> mine;  // triplets (row, col, value) of the owned rows
  auto rowMap = A.getRowMap();
  Teuchos::Array<GO> cols;
  Teuchos::Array<double> vals;
  for (size_t i = 0; i < A.getNodeNumRows(); ++i) {
    const GO g = rowMap->getGlobalElement(LO(i));
    const size_t nnz = A.getNumEntriesInGlobalRow(g);
    cols.resize(nnz);
    vals.resize(nnz);
    size_t got = 0;
    A.getGlobalRowCopy(g, cols(), vals(), got);
    for (size_t k = 0; k < got; ++k) {
      mine.push_back(double(g));
      mine.push_back(double(cols[k]));
      mine.push_back(vals[k]);
    }
  }
  std::vector<int> counts(size), displs(size);
  int count = static_cast<int>(mine.size());
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
    all.resize(displs[size - 1] + counts[size - 1]);
  }
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  std::vector<double> dense;
  if (rank != 0) return dense;
  dense.assign(size_t(n) * n, 0.0);
  for (size_t k = 0; k + 2 < all.size(); k += 3)
    dense[size_t(all[k + 1]) * n + size_t(all[k])] += all[k + 2];
  return dense;
}

}  // namespace

EigenResult solveDenseEigenproblem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M,
                                   const EigenRequest& req) {
  const long long n = static_cast<long long>(K->getGlobalNumRows());
  if (n > kDenseEigenMaxUnknowns)
    throw InputError("Modal analysis: 'Method' = 'dense' is for models of at most " +
                     std::to_string(kDenseEigenMaxUnknowns) + " unknowns (this one has " +
                     std::to_string(n) + "); use 'Krylov-Schur'");
  if (req.numModes < 1 || req.numModes > n)
    throw InputError("Modal analysis: 'Number of Modes' = " + std::to_string(req.numModes) +
                     " must be between 1 and " + std::to_string(n) + " (the model's unknowns)");
  const int rank = K->getComm()->getRank();
  std::vector<double> lambda(n), vecs;
  int info = 0;
  {
    std::vector<double> A = denseOnRoot(*K, n), B = denseOnRoot(*M, n);
    if (rank == 0) {
      Teuchos::LAPACK<int, double> lapack;
      int lwork = -1;
      double query = 0;
      lapack.SYGV(1, 'V', 'U', int(n), A.data(), int(n), B.data(), int(n), lambda.data(), &query,
                  lwork, &info);
      lwork = std::max<int>(1, int(query));
      std::vector<double> work(lwork);
      lapack.SYGV(1, 'V', 'U', int(n), A.data(), int(n), B.data(), int(n), lambda.data(),
                  work.data(), lwork, &info);
      vecs.swap(A);  // eigenvectors, B-normalised, column-major
    }
  }
  MPI_Bcast(&info, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (info != 0)
    throw NumericalError("dense eigen-solve (LAPACK DSYGV) failed with info = " +
                         std::to_string(info) + (info > n ? " (mass matrix not positive definite)" : ""));
  MPI_Bcast(lambda.data(), int(n), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  // The requested modes: nearest the shift, then sorted ascending.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(lambda[a] - req.shift) < std::abs(lambda[b] - req.shift);
  });
  order.resize(req.numModes);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lambda[a] < lambda[b]; });
  // Distribute the chosen columns.
  std::vector<double> chosen(size_t(n) * req.numModes);
  if (rank == 0)
    for (int k = 0; k < req.numModes; ++k)
      std::copy_n(&vecs[size_t(order[k]) * n], n, &chosen[size_t(k) * n]);
  MPI_Bcast(chosen.data(), int(chosen.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  EigenResult res;
  res.vectors = rcp(new MultiVector(K->getDomainMap(), req.numModes));
  auto map = K->getDomainMap();
  for (int k = 0; k < req.numModes; ++k) {
    auto col = res.vectors->getDataNonConst(k);
    for (size_t i = 0; i < res.vectors->getLocalLength(); ++i)
      col[i] = chosen[size_t(k) * n + size_t(map->getGlobalElement(LO(i)))];
    res.eigenvalues.push_back(lambda[order[k]]);
  }
  finishEigenResult(*K, *M, req.shift, res);
  return res;
}

}  // namespace choc
