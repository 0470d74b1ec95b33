// KLU2 on MPI_COMM_SELF for a matrix every rank holds (header).
#include "solvers/ReplicatedSparseLU.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/TpetraTypes.hpp"

namespace choc {

struct ReplicatedSparseLU::Impl {
  RCP<const Map> map;
  RCP<CrsMatrix> A;
  RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver;
  mutable RCP<MultiVector> x, b;
};

ReplicatedSparseLU::ReplicatedSparseLU() : impl_(new Impl) {}
ReplicatedSparseLU::~ReplicatedSparseLU() = default;

bool ReplicatedSparseLU::factor(int m, const std::vector<Entry>& entries) {
  m_ = m;
  Impl& s = *impl_;
  s.solver = Teuchos::null;
  if (m == 0) return true;
  std::vector<std::map<GO, double>> rows(static_cast<size_t>(m));
  for (const Entry& e : entries) rows[size_t(e.row)][GO(e.col)] += e.value;
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  s.map = rcp(new Map(Tpetra::global_size_t(m), size_t(m), 0, self));
  std::vector<size_t> counts(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) counts[size_t(i)] = std::max<size_t>(rows[size_t(i)].size(), 1);
  s.A = rcp(new CrsMatrix(s.map, Teuchos::ArrayView<const size_t>(counts)));
  std::vector<GO> cols;
  std::vector<double> vals;
  for (int i = 0; i < m; ++i) {
    cols.clear(), vals.clear();
    for (const auto& [j, v] : rows[size_t(i)]) cols.push_back(j), vals.push_back(v);
    if (cols.empty()) cols.push_back(GO(i)), vals.push_back(0.0);  // an empty row: singular
    s.A->insertGlobalValues(GO(i), Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  s.A->fillComplete(s.map, s.map);
  s.x = rcp(new MultiVector(s.map, 1));
  s.b = rcp(new MultiVector(s.map, 1));
  try {
    s.solver = Amesos2::create<CrsMatrix, MultiVector>("KLU2", s.A);
    s.solver->symbolicFactorization();
    s.solver->numericFactorization();
  } catch (const std::exception&) {
    s.solver = Teuchos::null;
    return false;
  }
  // A x = A 1: a (nearly) dependent row leaves x far from 1 or not finite.
  MultiVector ones(s.map, 1);
  ones.putScalar(1.0);
  s.A->apply(ones, *s.b);
  std::vector<double> y(static_cast<size_t>(m));
  {
    auto b = s.b->getData(0);
    std::copy(b.begin(), b.end(), y.begin());
  }
  solve(y);
  double err = 0.0;
  for (double v : y) err = std::max(err, std::abs(v - 1.0));
  if (!(err <= 1e-6)) {
    s.solver = Teuchos::null;
    return false;
  }
  return true;
}

void ReplicatedSparseLU::solve(std::vector<double>& y) const {
  if (m_ == 0) return;
  const Impl& s = *impl_;
  {
    auto b = s.b->getDataNonConst(0);
    std::copy(y.begin(), y.end(), b.begin());
  }
  s.solver->solve(Teuchos::ptr(s.x.get()), Teuchos::ptr(s.b.get()));
  auto x = s.x->getData(0);
  std::copy(x.begin(), x.end(), y.begin());
}

}  // namespace choc
