// The element eigenvalue bound of the critical step (Irons and Treharne 1971): for K = sum_e K_e
// and a lumped M = sum_e M_e, both on the unknowns, every eigenvalue of K x = lambda M x lies
// below the largest element eigenvalue max_e lambda_max(K_e, M_e), each element restricted to
// its unknown DOFs (a Rayleigh quotient of sums is at most the largest quotient of its terms).
// On a uniform bar of 2-node elements it gives 4 c^2 / h^2, the exact highest eigenvalue of a
// free chain (dt = h / c); in 3D it is far tighter than Gershgorin's row sums, which add the
// off-diagonal couplings of every element meeting at a node.
#pragma once
#include <limits>
#include <vector>

#include "fem/DenseMatrix.hpp"

namespace choc {

// lambda_max(K, M) on the rows and columns flagged in `active`, M diagonal there. Returns +inf
// when M has an off-diagonal entry on them, or a diagonal entry that is not positive where K's
// row is not zero (the bound does not apply); 0 when no active row carries stiffness.
double elementEigenvalue(const DenseMatrix& K, const DenseMatrix& M, const std::vector<char>& active);

}  // namespace choc
