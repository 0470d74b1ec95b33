// Generalized symmetric eigenproblem K x = lambda M x by dense LAPACK (DSYGV) on rank 0, for
// small models where the complete basis (or the modes nearest a shift among all of them) is
// wanted: Krylov-Schur cannot return the last two modes of a model. The result has the same
// form and checks as solveEigenproblem (ascending, M-normalised, true residuals).
#pragma once
#include "solvers/EigenSolver.hpp"

namespace choc {

// Largest model the dense path accepts (memory 2 n^2 doubles on rank 0).
constexpr long long kDenseEigenMaxUnknowns = 4000;

// request.numModes <= n; request.shift selects the modes nearest it when numModes < n
// (shift below every eigenvalue: the lowest).
EigenResult solveDenseEigenproblem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M,
                                   const EigenRequest& request);

}  // namespace choc
