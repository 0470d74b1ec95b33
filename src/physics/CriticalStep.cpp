#include "physics/CriticalStep.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/MatrixOps.hpp"

namespace choc {

namespace {

// M_ii of the given DOFs (global ids, -1: none -> 0), the same on every rank.
std::vector<double> gatheredMasses(const Vector& massDiagonal, const std::vector<GO>& dofs) {
  auto map = massDiagonal.getMap();
  auto md = massDiagonal.getData();
  std::vector<double> mine(dofs.size(), 0.0), all(dofs.size(), 0.0);
  for (size_t k = 0; k < dofs.size(); ++k) {
    if (dofs[k] < 0) continue;
    const LO l = map->getLocalElement(dofs[k]);
    if (l != Teuchos::OrdinalTraits<LO>::invalid()) mine[k] = md[l];
  }
  if (!dofs.empty())
    Teuchos::reduceAll<int, double>(*map->getComm(), Teuchos::REDUCE_SUM, int(dofs.size()), mine.data(),
                                    all.data());
  return all;
}

// rows[local row] += k |b_i| sum_j |b_j| / sqrt(m_i m_j) for a coupling k b b^T on `dofs`.
void addCoupling(const Map& rowMap, const std::vector<GO>& dofs, const std::vector<double>& b,
                 const std::vector<double>& masses, double k, std::vector<double>& rows) {
  for (size_t i = 0; i < dofs.size(); ++i) {
    if (dofs[i] < 0 || !(masses[i] > 0)) continue;
    const LO l = rowMap.getLocalElement(dofs[i]);
    if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    double s = 0.0;
    for (size_t j = 0; j < dofs.size(); ++j)
      if (dofs[j] >= 0 && masses[j] > 0) s += std::abs(b[j]) / std::sqrt(masses[j]);
    rows[l] += k * std::abs(b[i]) / std::sqrt(masses[i]) * s;
  }
}

}  // namespace

RCP<Vector> lumpedMassDiagonal(const CrsMatrix& M) {
  auto rowMap = M.getRowMap();
  auto d = rcp(new Vector(rowMap));
  int bad = 0;
  {
    auto dd = d->getDataNonConst();
    RowCopy row;
    for (size_t i = 0; i < rowMap->getNodeNumElements(); ++i) {
      const GO g = rowMap->getGlobalElement(LO(i));
      row.read(M, g);
      double diag = 0.0;
      for (size_t k = 0; k < row.size; ++k) {
        if (row.cols[k] == g) diag += row.vals[k];
        else if (row.vals[k] != 0.0) bad = 1;
      }
      if (!(diag > 0)) bad = 1;
      dd[i] = diag;
    }
  }
  int anyBad = 0;
  Teuchos::reduceAll<int, int>(*rowMap->getComm(), Teuchos::REDUCE_MAX, bad, Teuchos::outArg(anyBad));
  return anyBad ? RCP<Vector>() : d;
}

FrequencyBound omegaMaxBound(const CrsMatrix& K, const Vector& massDiagonal, const ContactManager* contact,
                             double contactStiffness, const DirectLinks* links, double meshBound) {
  auto rowMap = K.getRowMap();
  auto colMap = K.getColMap();
  Vector mCol(colMap);
  mCol.doImport(massDiagonal, Tpetra::Import<LO, GO>(rowMap, colMap), Tpetra::INSERT);
  auto mc = mCol.getData();
  auto md = massDiagonal.getData();
  const size_t nLocal = rowMap->getNodeNumElements();
  std::vector<double> rows(nLocal, 0.0), couplings(nLocal, 0.0);
  RowCopy row;
  for (size_t i = 0; i < nLocal; ++i) {
    row.read(K, rowMap->getGlobalElement(LO(i)));
    for (size_t k = 0; k < row.size; ++k)
      rows[i] += std::abs(row.vals[k]) / std::sqrt(md[i] * mc[colMap->getLocalElement(row.cols[k])]);
  }
  if (contact && contactStiffness > 0)
    for (const ContactConstraint& c : contact->constraints()) {
      std::vector<GO> dofs;
      std::vector<double> b;
      for (const auto& [gid, coef] : c.terms) dofs.push_back(gid), b.push_back(coef);
      addCoupling(*rowMap, dofs, b, gatheredMasses(massDiagonal, dofs), contactStiffness, couplings);
    }
  if (links)
    for (size_t i = 0; i < links->links().size(); ++i) {
      const ShockLawParameters& law = links->links()[i].law;
      const std::vector<GO> dofs = links->linkDofs(i);
      // A unit force along any direction: |b| <= 1 per component, on both nodes.
      addCoupling(*rowMap, dofs, std::vector<double>(dofs.size(), 1.0), gatheredMasses(massDiagonal, dofs),
                  std::max(law.normalStiffness, law.tangentialStiffness), couplings);
    }
  double mine[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};
  for (size_t i = 0; i < nLocal; ++i) {
    mine[0] = std::max(mine[0], rows[i] + couplings[i]);
    mine[1] = std::max(mine[1], couplings[i]);
  }
  Teuchos::reduceAll<int, double>(*rowMap->getComm(), Teuchos::REDUCE_MAX, 2, mine, all);
  FrequencyBound f;
  f.gershgorin = std::sqrt(all[0]);
  f.element = std::sqrt(meshBound + all[1]);
  f.omegaMax = std::min(f.element, f.gershgorin);
  return f;
}

}  // namespace choc
