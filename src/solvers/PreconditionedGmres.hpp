// GMRES (no restart, right preconditioning with the preconditioned basis kept, as flexible
// GMRES does, so the solution costs no further solve; modified Gram-Schmidt, Givens rotations) for
// A x = b with a preconditioner given as a function z = P^-1 v. A direct solver uses it with
// the factorisation of an earlier matrix as P: when A differs from that matrix in r rows,
// A P^-1 = I + (rank <= r), so GMRES converges in at most r + 1 iterations in exact
// arithmetic (a low-rank update of the factorisation, applied by Krylov iterations instead of
// an explicit Sherman-Morrison-Woodbury formula).
#pragma once
#include <functional>
#include <string>

#include "core/TpetraTypes.hpp"

namespace choc {

struct GmresOutcome {
  bool converged = false;
  int iterations = 0;             // preconditioned solves beyond the first (x0 = P^-1 b)
  double estimatedResidual = 0;  // GMRES's own ||b - A x|| / ||b|| estimate
  std::string failure;           // a preconditioner failure (empty otherwise)
};

// Starts from x = P^-1 b (0 iterations when that solves A x = b to tol); stops when the estimated relative residual is at most tol or after
// maxIterations. The preconditioner returns "" or its failure's message.
GmresOutcome preconditionedGmres(const CrsMatrix& A,
                                 const std::function<std::string(const Vector&, Vector&)>& precondition,
                                 const Vector& b, Vector& x, double tol, int maxIterations);

}  // namespace choc
