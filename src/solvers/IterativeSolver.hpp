// Belos Krylov solver (CG, GMRES, MINRES) preconditioned by Ifpack2 (RILUK, ILUT, Jacobi,
// Gauss-Seidel, or none).
#pragma once
#include "solvers/LinearSolver.hpp"

namespace choc {

std::unique_ptr<LinearSolver> makeIterativeSolver(const Teuchos::ParameterList& params);

}  // namespace choc
