// Amesos2 sparse direct solver (KLU2 by default): symbolic once per structure, numeric per
// setMatrix().
#pragma once
#include "solvers/LinearSolver.hpp"

namespace choc {

std::unique_ptr<LinearSolver> makeDirectSolver(const std::string& package, double residualTolerance);

}  // namespace choc
