// The sparse direct solver: a factorisation backend (solvers/FactorizationBackend.hpp: Amesos2
// KLU2 on rank 0 by default, or MUMPS on every rank), symbolic once per structure, numeric per
// setMatrix(); after updateMatrix() the numeric factorisation may be kept (GMRES on it).
#pragma once
#include "solvers/LinearSolver.hpp"

namespace choc {

// budget: preconditioned solves a kept factorisation may spend after updateMatrix() before a
// refactorisation (0: always refactor; -1: by the size, see DirectSolver.cpp).
// Throws InputError for a package this build does not have.
// symmetric: every matrix set will be symmetric (a package may factor half of it).
// capacitance: a kept factorisation solves changed rows by the capacitance form first
// (solvers/CapacitanceUpdate.hpp), else by GMRES alone.
std::unique_ptr<LinearSolver> makeDirectSolver(const std::string& package, double residualTolerance,
                                               int budget = -1, bool symmetric = false,
                                               bool capacitance = true);

}  // namespace choc
