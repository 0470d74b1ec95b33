// The multipliers as unknowns of the Newton system: W extended by one row per constraint (global
// id nU + s, owned by the slave node's rank), whose unknown is lambda_s / S (S the active set's
// scale, a typical diagonal of W: a balanced system):
//     [ aM M + aK K + sum_active k_s B_s^T B_s   -S B_A^T      ] [du        ]   [ -r               ]
//     [ -S B_A                                    S I_inactive ] [dlambda/S ] = [ -rowResidual(s)  ]
// An active row reads g_s = 0, an inactive one lambda_s = 0. The graph holds every coupling, so a
// change of statuses keeps the sparsity (a direct solver keeps its symbolic factorisation).
#include "contact/ContactStrategies.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

void SaddlePointStrategy::appendRows(GO nU, int rank, std::vector<GO>& gids) {
  rowOfConstraint_.assign(size_t(geometry_.numConstraints()), -1);
  for (int s = 0; s < geometry_.numConstraints(); ++s)
    if (geometry_.constraints()[s].owner == rank) {
      rowOfConstraint_[s] = LO(gids.size());
      gids.push_back(nU + s);
    }
}

void SaddlePointStrategy::addConstraintEntries(int s, const Map& dofMap, GO nU, std::vector<MatrixEntry>& out) const {
  const ContactActiveSet& set = geometry_.activeSet();
  const double S = set.scale, k = geometry_.method().stiffness();
  const bool active = set.status[s];
  const auto& terms = geometry_.constraints()[s].terms;
  for (const auto& [di, bi] : terms) {
    if (dofMap.getLocalElement(di) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    if (active && k != 0.0)
      for (const auto& [dj, bj] : terms) out.push_back({di, dj, k * bi * bj});
    if (active) out.push_back({di, nU + s, -S * bi});
  }
  if (rowOfConstraint_[s] < 0) return;
  const GO row = nU + s;
  if (active) {
    for (const auto& [dj, bj] : terms) out.push_back({row, dj, -S * bj});
  } else {
    out.push_back({row, row, S});
  }
}

void SaddlePointStrategy::rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) {
  ContactStrategy::rightHandSide(W, r, u, b);
  auto bd = b.getDataNonConst(0);
  const std::vector<double> g = geometry_.gaps(u);
  for (int s = 0; s < geometry_.numConstraints(); ++s)
    if (rowOfConstraint_[s] >= 0) bd[rowOfConstraint_[s]] = -geometry_.activeSet().rowResidual(s, g[s]);
}

void SaddlePointStrategy::takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) {
  ContactStrategy::takeSolution(W, x, du);
  auto xd = x.getData(0);
  const int nS = geometry_.numConstraints();
  std::vector<double> mine(nS, 0.0), all(nS, 0.0);
  for (int s = 0; s < nS; ++s)
    if (rowOfConstraint_[s] >= 0) mine[s] = xd[rowOfConstraint_[s]];
  Teuchos::reduceAll<int, double>(*geometry_.comm(), Teuchos::REDUCE_SUM, nS, mine.data(), all.data());
  geometry_.activeSet().applyCorrection(all);
}

}  // namespace choc
