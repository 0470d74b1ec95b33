// What a direct solver factors with. solvers/DirectSolver.cpp keeps, refines and updates a
// factorisation the same way whatever the backend:
//   - Amesos2 (KLU2 and the packages this Trilinos has) on rank 0: the system is gathered
//     there (Debian's Trilinos 13.2 KLU2 returns wrong solutions on a communicator of more than
//     one rank), so the factorisation does not scale with the ranks;
//   - MUMPS (Debian libmumps-dev) on every rank: each rank gives its rows (distributed
//     assembled input), the analysis (ordering, symbolic factorisation) is made once per graph
//     and the numerical factorisation per matrix; right-hand side and solution are gathered on
//     rank 0 for the solve phase, which is MUMPS' own distributed triangular solve.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

class FactorizationBackend {
 public:
  virtual ~FactorizationBackend() = default;
  // Factors A (collective). The failure's message, the same on every rank ("" on success).
  virtual std::string factor(RCP<const CrsMatrix> A) = 0;
  // x = A^-1 b with the last factorisation (collective). The failure's message or "".
  virtual std::string solve(const MultiVector& b, MultiVector& x) = 0;
  virtual std::string name() const = 0;
  // The entries of the last factorisation's factors, summed over the ranks (0: unknown), which
  // bound the capacitance form's columns (solvers/DirectSolver.cpp; unknown: 8 times the
  // matrix's entries).
  virtual double factorEntries() const { return 0.0; }
  // The same as counted for the cost of a factorisation (the kept factorisation's budget): also
  // Amesos2's count, which the capacitance form's bound does not use (its columns keep their
  // measured estimate there).
  virtual double countedFactorEntries() const { return factorEntries(); }
  // Right-hand sides solved in one block for the cost of one solved alone (rounded down).
  virtual int columnsPerSolve() const { return 1; }
};

// Amesos2's `package` on rank 0 (query with amesos2Available first).
std::unique_ptr<FactorizationBackend> makeAmesos2RootBackend(const std::string& package);
bool amesos2Available(const std::string& package);
// MUMPS on every rank of A's communicator; null when this build has no MUMPS. `symmetric`: every
// matrix set will be symmetric (LDL^T on half of it where each rank's block confirms it).
std::unique_ptr<FactorizationBackend> makeMumpsBackend(bool symmetric = false);
bool mumpsAvailable();
// The Amesos2 packages this build has (KLU2 first).
std::vector<std::string> amesos2Packages();
// The direct packages this build offers: KLU2 first, then the other Amesos2 packages it has,
// then MUMPS when built with it.
std::vector<std::string> directPackages();

}  // namespace choc
