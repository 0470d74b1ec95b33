// Sparse matrix combinations used by solvers and integrators.
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

// a A + b B (union of the two sparsity patterns), fill-completed on A's maps.
RCP<CrsMatrix> addMatrices(double a, const CrsMatrix& A, double b, const CrsMatrix& B);

}  // namespace choc
