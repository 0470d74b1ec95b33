// The initial acceleration of a model whose mass matrix has zero rows (the redistributed
// contact mass makes the contact surfaces' DOFs massless): M a0 = -r cannot be solved as it
// stands; the massless rows are the static equilibrium's second time derivative instead
// (MasslessInitialAcceleration.cpp). The structural operator calls it before the first step.
#pragma once
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "core/TpetraTypes.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

// The rows of M without a non-zero entry: per local row, and their count over all ranks.
struct MasslessRows {
  std::vector<char> mask;
  long long global = 0;
};
MasslessRows masslessRows(const CrsMatrix& M);

// a0 on every DOF from the residual r at the initial state (r = F(u0, v0, t0) + f_c(u0)),
// with K the stiffness, M the mass and `massless` its zero rows (local); the solver is left
// holding A0's factorisation (the caller refactors its own matrix next).
CorrectionStatus solveMasslessInitialAcceleration(const CrsMatrix& K, const CrsMatrix& M,
                                                  const std::vector<char>& massless, LinearSolver& solver,
                                                  Teuchos::StackedTimer* timer, const Vector& r, Vector& a);

}  // namespace choc
