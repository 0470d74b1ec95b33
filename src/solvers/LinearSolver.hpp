// Solving A x = b for a sparse Tpetra matrix: Amesos2 direct (KLU2) or Belos Krylov
// (CG, GMRES, MINRES) with an Ifpack2 preconditioner, chosen by the "Linear Solver" sublist.
// The factorisation / preconditioner is computed by setMatrix() and reused by every solve()
// until setMatrix() is called again (callers key it on dt, scheme and active set).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/TpetraTypes.hpp"
#include "fem/NodalBlocks.hpp"
#include "solvers/ConstraintProjector.hpp"

namespace choc {

struct LinearSolveStatus {
  bool converged = false;
  int iterations = 0;          // 0 for a direct solve
  double relativeResidual = 0; // ||b - A x|| / ||b|| (recomputed, not trusted from the solver)
  std::string message;         // why it failed
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // Sets the matrix and computes the factorisation or the preconditioner. Throws
  // NumericalError when the matrix is singular or the factorisation fails.
  virtual void setMatrix(RCP<const CrsMatrix> A) = 0;
  // A has the graph of the matrix last set and differs from it in a few rows (a change of
  // contact status with the same effective coefficients). A direct solver may keep its
  // factorisation and solve by GMRES preconditioned by it (a low-rank update); by default,
  // and whenever that does not pay, it is setMatrix(A).
  virtual void updateMatrix(RCP<const CrsMatrix> A) { setMatrix(A); }
  // Whether updateMatrix() may keep the factorisation of the matrix last set.
  virtual bool mayKeepFactorization() const { return false; }
  // The state of a kept factorisation besides the matrices (for checkpoints), and back after
  // setMatrix(factored) and updateMatrix(current).
  virtual std::vector<long long> keptState() const { return {}; }
  virtual void restoreKeptState(const std::vector<long long>& /*state*/) {}
  // The following matrices' solves eliminate the projector's constraints (the operator and
  // preconditioner of solvers/ConstraintProjector.hpp; the projector may change between solves,
  // the preconditioner stays A's). False when this solver cannot (a direct solver).
  virtual bool setProjection(std::shared_ptr<const ConstraintProjector> /*projector*/) { return false; }
  virtual LinearSolveStatus solve(const MultiVector& b, MultiVector& x) = 0;
  virtual std::string description() const = 0;
  int factorizations() const { return factorizations_; }
  // Matrices given by updateMatrix() that were solved on the kept factorisation.
  int updates() const { return updates_; }
  // For the following solves: an iterative solver may stop once the relative residual is at
  // most max(its Tolerance, looser) (inexact Newton: no solve more exact than the Newton test
  // needs); a direct solver ignores it. 0 restores the Tolerance.
  void relaxTolerance(double looser) { looser_ = looser; }

 protected:
  int factorizations_ = 0;
  int updates_ = 0;
  double looser_ = 0.0;
};

// The valid "Linear Solver" sublist.
Teuchos::ParameterList linearSolverParameters();
// Builds from a validated "Linear Solver" sublist. symmetric: the caller knows every matrix it
// will set is symmetric (a direct package may then factor half of it). blocks: the model's
// unknowns node by node, which Preconditioner = Multigrid needs (InputError without).
std::unique_ptr<LinearSolver> makeLinearSolver(const Teuchos::ParameterList& params, bool symmetric = false,
                                               std::shared_ptr<const NodalBlocks> blocks = nullptr);

// ||b - A x|| / ||b|| for each column, returns the largest (0 when b = 0 and x = 0).
double relativeResidual(const CrsMatrix& A, const MultiVector& b, const MultiVector& x);
// || |A| |x| || / ||b|| for each column, the largest: the size of the terms A x sums, relative
// to b. The round-off of evaluating A x alone is about eps times it, so no solve can be shown
// to leave a smaller relative residual: for an ill-conditioned but regular matrix (a slender
// solid in bending: cond(A) ~ 1e8) it is the residual's floor.
double productTermsRatio(const CrsMatrix& A, const MultiVector& b, const MultiVector& x);

}  // namespace choc
