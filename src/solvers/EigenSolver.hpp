// Generalized symmetric eigenproblem K x = lambda M x by Anasazi Block Krylov-Schur on the
// shift-invert operator (K - sigma M)^-1 M, with an Amesos2 factorisation of K - sigma M.
// Returns the modes nearest sigma, sorted by increasing eigenvalue, M-normalised, each with
// its true residual ||K phi - lambda M phi|| / (||K phi|| + max(|lambda|,|sigma|) ||M phi||).
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

struct EigenRequest {
  int numModes = 10;
  double shift = 0.0;            // sigma, in eigenvalue units (rad/s)^2
  double tolerance = 1e-10;      // Anasazi convergence tolerance on the Ritz residual
  int maxRestarts = 200;
  std::string directPackage = "KLU2";
};

struct EigenResult {
  std::vector<double> eigenvalues;      // ascending
  RCP<MultiVector> vectors;             // one column per mode, M-normalised
  std::vector<double> generalizedMass;  // phi^T M phi (1 after normalisation)
  std::vector<double> residuals;        // true relative residuals
  int restarts = 0;  // solver iterations (getNumIters)
  int operatorApplies = 0;
};

// Normalises res.vectors to unit generalized mass (sign: largest entry positive is not
// enforced) and fills res.generalizedMass and res.residuals (true residuals).
void finishEigenResult(const CrsMatrix& K, const CrsMatrix& M, double shift, EigenResult& res);

// Throws InputError for an impossible request (more modes than unknowns) and NumericalError
// when Anasazi does not converge the requested number of modes.
EigenResult solveEigenproblem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M,
                              const EigenRequest& request);

}  // namespace choc
