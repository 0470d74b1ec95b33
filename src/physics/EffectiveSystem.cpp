#include "physics/EffectiveSystem.hpp"

#include <algorithm>
#include <iterator>
#include <map>

#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include "physics/SystemGraph.hpp"
#include "fem/MatrixOps.hpp"

namespace choc {

EffectiveSystem::EffectiveSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, ContactStrategy* contact,
                                 const std::vector<std::vector<GO>>& couplings)
    : K_(std::move(K)), M_(std::move(M)), contact_(contact) {
  maxDiagK_ = largestDiagonal(*K_);
  maxDiagM_ = largestDiagonal(*M_);
  auto dofMap = K_->getRowMap();
  nLocalDofs_ = dofMap->getNodeNumElements();
  if (contact_) contact_->attach(dofMap);
  if (contact_ && contact_->extendsSystem()) {
    std::vector<GO> gids(dofMap->getNodeElementList().begin(), dofMap->getNodeElementList().end());
    contact_->appendRows(GO(dofMap->getGlobalNumElements()), dofMap->getComm()->getRank(), gids);
    map_ = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                       Teuchos::ArrayView<const GO>(gids), 0, dofMap->getComm()));
  } else {
    map_ = dofMap;
  }
  buildMatrix(couplings);
}

// Graph: K and M patterns and every row's diagonal (SystemGraph), then every contact coupling
// and the links' couplings.
void EffectiveSystem::buildMatrix(const std::vector<std::vector<GO>>& couplings) {
  const auto dofMap = K_->getRowMap();
  std::map<LO, std::vector<GO>> extra;
  if (contact_) contact_->addCouplings(*dofMap, GO(dofMap->getGlobalNumElements()), extra);
  for (const auto& group : couplings)
    for (GO di : group) {
      const LO l = dofMap->getLocalElement(di);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) extra[l].insert(extra[l].end(), group.begin(), group.end());
    }
  SystemGraph sg = buildSystemGraph(*K_, *M_, map_, nLocalDofs_, extra);
  // The values are left unzeroed: the first fill writes every row (and zeroes it first).
  using Values = typename CrsMatrix::local_matrix_device_type::values_type;
  A_ = rcp(new CrsMatrix(sg.graph, Values(Kokkos::ViewAllocateWithoutInitializing("system values"),
                                          sg.graph->getNodeNumEntries())));
  A_->fillComplete(map_, map_);
  colOfK_ = std::move(sg.fromK);
  colOfM_ = std::move(sg.fromM);
  slot_.assign(A_->getColMap()->getNodeNumElements(), -1);
}

// Row i of the DOF block takes aK K(i,:) + aM M(i,:); A's pattern holds both. The values are
// written through the local matrix (a search per entry by global index cost 0.37 s per fill
// at 300,000 unknowns). rows: the local rows to write (null: all), each zeroed first.
void EffectiveSystem::fillBulk(double aM, double aK, const std::vector<LO>* rows) {
  const auto A = A_->getLocalMatrixHost();
  const auto Kl = K_->getLocalMatrixHost(), Ml = M_->getLocalMatrixHost();
  auto add = [&](const decltype(Kl)& X, const std::vector<LO>& colOf, double a, size_t i, size_t b) {
    if (a == 0.0) return;
    for (auto k = X.graph.row_map(i); k < X.graph.row_map(i + 1); ++k)
      A.values(b + slot_[colOf[X.graph.entries(k)]]) += a * X.values(k);
  };
  auto row = [&](size_t i) {
    const auto b = A.graph.row_map(i), e = A.graph.row_map(i + 1);
    for (auto k = b; k < e; ++k) A.values(k) = 0.0;
    if (i >= nLocalDofs_) return;  // a multiplier row: contact terms only
    for (auto k = b; k < e; ++k) slot_[A.graph.entries(k)] = LO(k - b);
    add(Kl, colOfK_, aK, i, b);
    add(Ml, colOfM_, aM, i, b);
    for (auto k = b; k < e; ++k) slot_[A.graph.entries(k)] = -1;
  };
  if (rows) {
    for (LO i : *rows) row(size_t(i));
  } else {
    for (size_t i = 0; i + 1 < size_t(A.graph.row_map.extent(0)); ++i) row(i);
  }
}

// The entries added to aM M + aK K, in the order they are summed: the strategy's (its rows for
// the current statuses, friction's tangent), the extra entries.
void EffectiveSystem::fill(double aM, double aK, const std::vector<MatrixEntry>& extra) {
  std::vector<MatrixEntry> all;
  if (contact_) {
    contact_->setScale(std::max(aM * maxDiagM_ + aK * maxDiagK_, 1e-300));
    all = contact_->entries(*K_->getRowMap(), GO(K_->getRowMap()->getGlobalNumElements()));
  }
  all.insert(all.end(), extra.begin(), extra.end());
  fillEntries(aM, aK, all);
}

// A refill with the same (aM, aK) as the last one rewrites only the rows the last and the new
// coupling entries touch (a change of contact status, a new friction tangent): the other rows
// hold aM M + aK K already, so the values are those of a whole refill, bit for bit.
void EffectiveSystem::fillEntries(double aM, double aK, const std::vector<MatrixEntry>& all) {
  if (contact_) contact_->setScale(std::max(aM * maxDiagM_ + aK * maxDiagK_, 1e-300));
  std::vector<MatrixEntry> entries;  // the rows this rank owns (others are not summed)
  std::vector<LO> rows;
  for (const MatrixEntry& e : all) {
    const LO l = map_->getLocalElement(e.row);
    if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    rows.push_back(l);
    entries.push_back(e);
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  A_->resumeFill();
  if (filled_ && aM == lastAM_ && aK == lastAK_ && !(contact_ && contact_->rewritesEveryRow())) {
    std::vector<LO> both;
    std::set_union(rows.begin(), rows.end(), lastRows_.begin(), lastRows_.end(), std::back_inserter(both));
    fillBulk(aM, aK, &both);
  } else {
    fillBulk(aM, aK, nullptr);
  }
  // Eliminated multipliers: the entries in a multiplier's column (friction's d force / d lambda)
  // are not in the matrix; the strategy takes them.
  const GO nU = GO(K_->getRowMap()->getGlobalNumElements());
  const bool eliminated = contact_ && contact_->eliminatesMultipliers();
  std::vector<MatrixEntry> multiplierColumns;
  for (const MatrixEntry& e : entries) {
    if (eliminated && e.col >= nU) {
      multiplierColumns.push_back(e);
      continue;
    }
    A_->sumIntoGlobalValues(e.row, Teuchos::ArrayView<const GO>(&e.col, 1),
                            Teuchos::ArrayView<const double>(&e.value, 1));
  }
  if (eliminated) contact_->eliminate(A_, std::move(multiplierColumns), nU);
  A_->fillComplete(map_, map_);
  filled_ = true;
  lastAM_ = aM;
  lastAK_ = aK;
  lastRows_ = std::move(rows);
  lastEntries_ = std::move(entries);
}

void EffectiveSystem::rightHandSide(const Vector& r, const Vector& u, MultiVector& b) {
  if (contact_) return contact_->rightHandSide(*A_, r, u, b);
  auto rd = r.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < nLocalDofs_; ++i) bd[i] = -rd[i];
}

void EffectiveSystem::takeSolution(const MultiVector& x, Vector& du) {
  if (contact_) return contact_->takeSolution(*A_, x, du);
  auto xd = x.getData(0);
  auto d = du.getDataNonConst();
  for (size_t i = 0; i < nLocalDofs_; ++i) d[i] = xd[i];
}

}  // namespace choc
