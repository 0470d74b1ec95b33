// Belos Krylov solver (CG, GMRES, MINRES) preconditioned by Ifpack2 (RILUK, ILUT, Jacobi,
// Gauss-Seidel, Additive Schwarz, or none) or by MueLu (Multigrid: ElasticityMultigrid.hpp,
// which needs the model's node blocks).
#pragma once
#include <memory>

#include "fem/NodalBlocks.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {

std::unique_ptr<LinearSolver> makeIterativeSolver(const Teuchos::ParameterList& params,
                                                  std::shared_ptr<const NodalBlocks> blocks = nullptr);

}  // namespace choc
