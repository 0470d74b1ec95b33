// What a checkpoint carries when the direct solver keeps its factorisation through changes of
// contact status (LinearSolver::updateMatrix, 'Update Budget'): the coupling entries (contact
// block, friction and link tangents, gathered from every rank) of the factored matrix and of
// the last filled one, the effective coefficients both share, the status key of the last fill
// and the solver's own state. A run restarted on as many ranks refactors the same matrix, fills
// the last one and takes the same path as the run that wrote the checkpoint: bit for bit. On
// another rank count the DOF numbering differs and the restart starts from a fresh
// factorisation (equal to solver tolerance).
#pragma once
#include <vector>

#include "contact/ContactManager.hpp"
#include "core/TpetraTypes.hpp"
#include "restart/StateArchive.hpp"
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

struct KeptFactorization {
  EffectiveCoefficients coefficients;
  std::vector<MatrixEntry> factored, last;  // this rank's rows; every rank's once restored
  std::vector<char> keyStatus;
  std::vector<long long> solverState;

  // Collective: gathers the entries of every rank.
  void archive(StateArchive& a, const Comm& comm) const;
  // False when the archive holds none, or was written on another number of ranks.
  bool restore(const StateArchive& a, const Comm& comm);
};

// Every rank's entries, in rank order, on every rank.
std::vector<MatrixEntry> gatherEntries(const std::vector<MatrixEntry>& mine, const Comm& comm);

}  // namespace choc
