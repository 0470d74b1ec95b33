#include "contact/ContactSystem.hpp"

#include <algorithm>
#include <iterator>
#include <map>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include "contact/SystemGraph.hpp"
#include "fem/MatrixOps.hpp"

namespace choc {

ContactSystem::ContactSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, ContactManager* contact,
                             const std::vector<std::vector<GO>>& couplings, bool condense)
    : K_(std::move(K)), M_(std::move(M)), contact_(contact) {
  maxDiagK_ = largestDiagonal(*K_);
  maxDiagM_ = largestDiagonal(*M_);
  auto dofMap = K_->getRowMap();
  auto comm = dofMap->getComm();
  const int rank = comm->getRank();
  const GO nU = GO(dofMap->getGlobalNumElements());
  nLocalDofs_ = dofMap->getNodeNumElements();
  if (condense) eliminateMultipliers(dofMap);
  extended_ = contact_ && contact_->method().hasMultipliers() && contact_->numConstraints() > 0 && !condensation_ &&
              !projection_;
  const int nS = contact_ ? contact_->numConstraints() : 0;
  rowOfConstraint_.assign(nS, -1);

  std::vector<GO> gids(dofMap->getNodeElementList().begin(), dofMap->getNodeElementList().end());
  if (extended_) {
    for (int s = 0; s < nS; ++s)
      if (contact_->constraints()[s].owner == rank) {
        rowOfConstraint_[s] = LO(gids.size());
        gids.push_back(nU + s);
      }
    map_ = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                       Teuchos::ArrayView<const GO>(gids), 0, comm));
  } else {
    map_ = dofMap;
  }

  // Graph: K and M patterns and every row's diagonal (SystemGraph), then every contact
  // coupling and the links' couplings.
  std::map<LO, std::vector<GO>> extra;
  for (int s = 0; s < nS; ++s) {
    const auto& terms = contact_->constraints()[s].terms;
    for (const auto& [di, ciJ] : terms) {
      const LO l = dofMap->getLocalElement(di);
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      for (const auto& t : terms) extra[l].push_back(t.first);
      if (extended_) extra[l].push_back(nU + s);
      (void)ciJ;
    }
    if (extended_ && rowOfConstraint_[s] >= 0)
      for (const auto& t : terms) extra[rowOfConstraint_[s]].push_back(t.first);
  }
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

ContactSystem::~ContactSystem() = default;

// Node by node against obstacles alone, else projected where Lagrange has no friction.
void ContactSystem::eliminateMultipliers(const RCP<const Map>& dofMap) {
  if (!contact_) return;
  if (ContactCondensation::applies(*contact_))
    condensation_ = std::make_unique<ContactCondensation>(*contact_);
  else if (ContactProjection::applies(*contact_))
    projection_ = std::make_shared<ContactProjection>(*contact_, dofMap);
}

// Row i of the DOF block takes aK K(i,:) + aM M(i,:); A's pattern holds both. The values are
// written through the local matrix (a search per entry by global index cost 0.37 s per fill
// at 300,000 unknowns). rows: the local rows to write (null: all), each zeroed first.
void ContactSystem::fillBulk(double aM, double aK, const std::vector<LO>* rows) {
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

// The entries added to aM M + aK K, in the order they are summed: the contact block for the
// current statuses, the friction tangent, the extra entries.
std::vector<MatrixEntry> ContactSystem::couplingEntries(const std::vector<MatrixEntry>& extra) const {
  std::vector<MatrixEntry> out;
  auto dofMap = K_->getRowMap();
  const GO nU = GO(dofMap->getGlobalNumElements());
  if (contact_) {
    const double S = contact_->scale();
    const double k = contact_->method().stiffness();
    for (int s = 0; s < contact_->numConstraints(); ++s) {
      const auto& terms = contact_->constraints()[s].terms;
      const bool active = contact_->status()[s];
      for (const auto& [di, bi] : terms) {
        if (dofMap->getLocalElement(di) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
        if (active && k != 0.0)
          for (const auto& [dj, bj] : terms) out.push_back({di, dj, k * bi * bj});
        if (extended_ && active) out.push_back({di, nU + s, -S * bi});
      }
      if (extended_ && rowOfConstraint_[s] >= 0) {
        const GO row = nU + s;
        if (active) {
          for (const auto& [dj, bj] : terms) out.push_back({row, dj, -S * bj});
        } else {
          out.push_back({row, row, S});
        }
      }
    }
  }
  if (contact_ && contact_->hasFriction())
    for (const MatrixEntry& e : contact_->friction()->tangent(nU)) out.push_back(e);
  out.insert(out.end(), extra.begin(), extra.end());
  return out;
}

// A refill with the same (aM, aK) as the last one rewrites only the rows the last and the new
// coupling entries touch (a change of contact status, a new friction tangent): the other rows
// hold aM M + aK K already, so the values are those of a whole refill, bit for bit.
void ContactSystem::fill(double aM, double aK, const std::vector<MatrixEntry>& extra) {
  if (contact_) contact_->setScale(std::max(aM * maxDiagM_ + aK * maxDiagK_, 1e-300));
  fillEntries(aM, aK, couplingEntries(extra));
}

void ContactSystem::fillEntries(double aM, double aK, const std::vector<MatrixEntry>& all) {
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
  if (filled_ && aM == lastAM_ && aK == lastAK_ && !condensation_) {
    std::vector<LO> both;
    std::set_union(rows.begin(), rows.end(), lastRows_.begin(), lastRows_.end(), std::back_inserter(both));
    fillBulk(aM, aK, &both);
  } else {
    fillBulk(aM, aK, nullptr);
  }
  // Condensed: the entries in a multiplier's column (friction's d force / d lambda) are not
  // in the matrix; the condensation takes them.
  const GO nU = GO(K_->getRowMap()->getGlobalNumElements());
  std::vector<MatrixEntry> multiplierColumns;
  for (const MatrixEntry& e : entries) {
    if ((condensation_ || projection_) && e.col >= nU) {
      multiplierColumns.push_back(e);
      continue;
    }
    A_->sumIntoGlobalValues(e.row, Teuchos::ArrayView<const GO>(&e.col, 1),
                            Teuchos::ArrayView<const double>(&e.value, 1));
  }
  if (condensation_) condensation_->project(A_, multiplierColumns, nU);  // every row was rewritten above
  if (projection_) projection_->setMultiplierColumns(std::move(multiplierColumns), nU);
  A_->fillComplete(map_, map_);
  filled_ = true;
  lastAM_ = aM;
  lastAK_ = aK;
  lastRows_ = std::move(rows);
  lastEntries_ = std::move(entries);
}

std::vector<char> ContactSystem::statusKey() const {
  if (!contact_ || (projection_ && !contact_->hasFriction())) return {};  // projected: W holds no contact term
  std::vector<char> key = contact_->status();
  const int g = contact_->geometryVersion();  // the coefficients of curved obstacles' rows
  const char* b = reinterpret_cast<const char*>(&g);
  key.insert(key.end(), b, b + sizeof g);
  const std::vector<char> friction = contact_->hasFriction() ? contact_->friction()->key() : std::vector<char>{};
  key.insert(key.end(), friction.begin(), friction.end());
  return key;
}

void ContactSystem::rightHandSide(const Vector& r, const Vector& u, MultiVector& b) const {
  if (condensation_) return condensation_->rightHandSide(r, u, b);
  if (projection_) return projection_->rightHandSide(*A_, r, u, b);
  auto rd = r.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < nLocalDofs_; ++i) bd[i] = -rd[i];
  if (!extended_) return;
  const std::vector<double> g = contact_->gaps(u);
  for (int s = 0; s < contact_->numConstraints(); ++s)
    if (rowOfConstraint_[s] >= 0) bd[rowOfConstraint_[s]] = -contact_->rowResidual(s, g[s]);
}

void ContactSystem::takeSolution(const MultiVector& x, Vector& du) const {
  if (condensation_) return condensation_->takeSolution(x, du);
  if (projection_) return projection_->takeSolution(*A_, x, du);
  auto xd = x.getData(0);
  {
    auto d = du.getDataNonConst();
    for (size_t i = 0; i < nLocalDofs_; ++i) d[i] = xd[i];
  }
  if (!extended_) return;
  const int nS = contact_->numConstraints();
  std::vector<double> mine(nS, 0.0), all(nS, 0.0);
  for (int s = 0; s < nS; ++s)
    if (rowOfConstraint_[s] >= 0) mine[s] = xd[rowOfConstraint_[s]];
  Teuchos::reduceAll<int, double>(*K_->getComm(), Teuchos::REDUCE_SUM, nS, mine.data(), all.data());
  contact_->applyCorrection(all);
}

}  // namespace choc
