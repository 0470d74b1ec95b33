#include "physics/KeptFactorization.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace choc {

std::vector<MatrixEntry> gatherEntries(const std::vector<MatrixEntry>& mine, const Comm& comm) {
  const long long n = (long long)mine.size();
  long long end = 0, total = 0;
  Teuchos::scan<int, long long>(comm, Teuchos::REDUCE_SUM, 1, &n, &end);
  Teuchos::reduceAll<int, long long>(comm, Teuchos::REDUCE_SUM, n, Teuchos::outArg(total));
  // Each rank writes its slice of zero-padded arrays; the sums are exact.
  std::vector<long long> idx(2 * total, 0), allIdx(2 * total, 0);
  std::vector<double> val(total, 0.0), allVal(total, 0.0);
  for (long long k = 0; k < n; ++k) {
    const long long at = end - n + k;
    idx[2 * at] = mine[k].row;
    idx[2 * at + 1] = mine[k].col;
    val[at] = mine[k].value;
  }
  if (total > 0) {
    Teuchos::reduceAll<int, long long>(comm, Teuchos::REDUCE_SUM, int(2 * total), idx.data(), allIdx.data());
    Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_SUM, int(total), val.data(), allVal.data());
  }
  std::vector<MatrixEntry> all(total);
  for (long long k = 0; k < total; ++k) all[k] = {GO(allIdx[2 * k]), GO(allIdx[2 * k + 1]), allVal[k]};
  return all;
}

void KeptFactorization::archive(StateArchive& a, const Comm& comm) const {
  a.putInt("kept_factorization/ranks", comm.getSize());
  a.putVector("kept_factorization/coefficients",
              std::vector<double>{coefficients.ca, coefficients.cv, coefficients.cd});
  a.putVector("kept_factorization/factored", gatherEntries(factored, comm));
  a.putVector("kept_factorization/last", gatherEntries(last, comm));
  a.putBytes("kept_factorization/key", keyStatus);
  a.putVector("kept_factorization/solver", solverState);
}

bool KeptFactorization::restore(const StateArchive& a, const Comm& comm) {
  if (!a.has("kept_factorization/ranks") || a.getInt("kept_factorization/ranks") != comm.getSize())
    return false;
  const std::vector<double> c = a.getVector<double>("kept_factorization/coefficients", 3);
  coefficients = {c[0], c[1], c[2]};
  factored = a.getVector<MatrixEntry>("kept_factorization/factored");
  last = a.getVector<MatrixEntry>("kept_factorization/last");
  keyStatus = a.getVector<char>("kept_factorization/key");
  solverState = a.getVector<long long>("kept_factorization/solver");
  return true;
}

}  // namespace choc
