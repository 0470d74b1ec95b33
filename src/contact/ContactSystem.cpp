#include "contact/ContactSystem.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include "fem/MatrixOps.hpp"

namespace choc {

ContactSystem::ContactSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, ContactManager* contact,
                             const std::vector<std::vector<GO>>& couplings)
    : K_(std::move(K)), M_(std::move(M)), contact_(contact) {
  maxDiagK_ = largestDiagonal(*K_);
  maxDiagM_ = largestDiagonal(*M_);
  auto dofMap = K_->getRowMap();
  auto comm = dofMap->getComm();
  const int rank = comm->getRank();
  const GO nU = GO(dofMap->getGlobalNumElements());
  nLocalDofs_ = dofMap->getNodeNumElements();
  extended_ = contact_ && contact_->method().hasMultipliers() && contact_->numConstraints() > 0;
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

  // Graph: K and M patterns, then every contact coupling (sorted vectors, not sets: a
  // 300,000-row system has 25 million entries).
  std::vector<std::vector<GO>> cols(gids.size());
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocalDofs_; ++i) {
    auto& row = cols[i];
    for (const CrsMatrix* X : {K_.get(), M_.get()}) {
      const size_t n = X->getNumEntriesInGlobalRow(gids[i]);
      ci.resize(n);
      cv.resize(n);
      size_t got = 0;
      X->getGlobalRowCopy(gids[i], ci(), cv(), got);
      row.insert(row.end(), ci.begin(), ci.begin() + got);
    }
    row.push_back(gids[i]);
  }
  for (int s = 0; s < nS; ++s) {
    const auto& terms = contact_->constraints()[s].terms;
    for (const auto& [di, ciJ] : terms) {
      const LO l = dofMap->getLocalElement(di);
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      for (const auto& t : terms) cols[l].push_back(t.first);
      if (extended_) cols[l].push_back(nU + s);
      (void)ciJ;
    }
    if (extended_ && rowOfConstraint_[s] >= 0) {
      auto& row = cols[rowOfConstraint_[s]];
      for (const auto& t : terms) row.push_back(t.first);
      row.push_back(nU + s);
    }
  }
  for (const auto& group : couplings)
    for (GO di : group) {
      const LO l = dofMap->getLocalElement(di);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) cols[l].insert(cols[l].end(), group.begin(), group.end());
    }
  std::vector<size_t> counts(gids.size());
  for (size_t i = 0; i < gids.size(); ++i) {
    auto& row = cols[i];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    counts[i] = row.size();
  }
  auto graph = rcp(new Tpetra::CrsGraph<LO, GO>(map_, Teuchos::ArrayView<const size_t>(counts)));
  for (size_t i = 0; i < gids.size(); ++i) {
    graph->insertGlobalIndices(gids[i], Teuchos::ArrayView<const GO>(cols[i]));
    std::vector<GO>().swap(cols[i]);
  }
  graph->fillComplete(map_, map_);
  A_ = rcp(new CrsMatrix(graph));
  A_->fillComplete(map_, map_);
}

void ContactSystem::fill(double aM, double aK, const std::vector<MatrixEntry>& extra) {
  if (contact_) contact_->setScale(std::max(aM * maxDiagM_ + aK * maxDiagK_, 1e-300));
  A_->resumeFill();
  A_->setAllToScalar(0.0);
  auto dofMap = K_->getRowMap();
  const GO nU = GO(dofMap->getGlobalNumElements());
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocalDofs_; ++i) {
    const GO g = dofMap->getGlobalElement(LO(i));
    for (const auto& [X, a] : {std::make_pair(K_.get(), aK), std::make_pair(M_.get(), aM)}) {
      if (a == 0.0) continue;
      const size_t n = X->getNumEntriesInGlobalRow(g);
      ci.resize(n);
      cv.resize(n);
      size_t got = 0;
      X->getGlobalRowCopy(g, ci(), cv(), got);
      for (size_t k = 0; k < got; ++k) cv[k] *= a;
      A_->sumIntoGlobalValues(g, ci(0, got), cv(0, got));
    }
  }
  if (contact_) {
    const double S = contact_->scale();
    const double k = contact_->method().stiffness();
    for (int s = 0; s < contact_->numConstraints(); ++s) {
      const auto& terms = contact_->constraints()[s].terms;
      const bool active = contact_->status()[s];
      for (const auto& [di, bi] : terms) {
        if (dofMap->getLocalElement(di) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
        if (active && k != 0.0)
          for (const auto& [dj, bj] : terms) {
            const GO c = dj;
            const double v = k * bi * bj;
            A_->sumIntoGlobalValues(di, Teuchos::ArrayView<const GO>(&c, 1),
                                    Teuchos::ArrayView<const double>(&v, 1));
          }
        if (extended_ && active) {
          const GO c = nU + s;
          const double v = -S * bi;
          A_->sumIntoGlobalValues(di, Teuchos::ArrayView<const GO>(&c, 1),
                                  Teuchos::ArrayView<const double>(&v, 1));
        }
      }
      if (extended_ && rowOfConstraint_[s] >= 0) {
        const GO row = nU + s;
        if (active) {
          for (const auto& [dj, bj] : terms) {
            const GO c = dj;
            const double v = -S * bj;
            A_->sumIntoGlobalValues(row, Teuchos::ArrayView<const GO>(&c, 1),
                                    Teuchos::ArrayView<const double>(&v, 1));
          }
        } else {
          const double v = S;
          A_->sumIntoGlobalValues(row, Teuchos::ArrayView<const GO>(&row, 1),
                                  Teuchos::ArrayView<const double>(&v, 1));
        }
      }
    }
  }
  if (contact_ && contact_->hasFriction())
    for (const MatrixEntry& e : contact_->frictionTangent(nU))
      A_->sumIntoGlobalValues(e.row, Teuchos::ArrayView<const GO>(&e.col, 1),
                              Teuchos::ArrayView<const double>(&e.value, 1));
  for (const MatrixEntry& e : extra)
    A_->sumIntoGlobalValues(e.row, Teuchos::ArrayView<const GO>(&e.col, 1),
                            Teuchos::ArrayView<const double>(&e.value, 1));
  A_->fillComplete(map_, map_);
}

std::vector<char> ContactSystem::statusKey() const {
  if (!contact_) return {};
  std::vector<char> key = contact_->status();
  const int g = contact_->geometryVersion();  // the coefficients of curved obstacles' rows
  const char* b = reinterpret_cast<const char*>(&g);
  key.insert(key.end(), b, b + sizeof g);
  const std::vector<char> friction = contact_->frictionKey();
  key.insert(key.end(), friction.begin(), friction.end());
  return key;
}

void ContactSystem::rightHandSide(const Vector& r, const Vector& u, MultiVector& b) const {
  auto rd = r.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < nLocalDofs_; ++i) bd[i] = -rd[i];
  if (!extended_) return;
  const std::vector<double> g = contact_->gaps(u);
  for (int s = 0; s < contact_->numConstraints(); ++s)
    if (rowOfConstraint_[s] >= 0) bd[rowOfConstraint_[s]] = -contact_->rowResidual(s, g[s]);
}

void ContactSystem::takeSolution(const MultiVector& x, Vector& du) const {
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
