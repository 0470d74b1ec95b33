// Distributed vectors to whole-model arrays on every rank (for output, links and checks).
#pragma once
#include <array>
#include <vector>

#include "fem/DofMap.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

// Column `col` of a vector on the DofMap's distribution, as a global-DOF-ordered array on
// every rank.
std::vector<double> gatherAll(const MultiVector& v, size_t col, const DofMap& dofs);
// One value per node for component `comp` of a global DOF array (0 where not an unknown).
std::vector<double> nodalComponent(const std::vector<double>& global, const DofMap& dofs, int comp);

}  // namespace choc

namespace choc {

// Rows of a distributed multivector at the given global DOFs (-1 rows are zero), on every
// rank: out[i * numVectors + k] = V(dofs[i], k).
std::vector<double> gatherRows(const MultiVector& V, const std::vector<long long>& dofs);

}  // namespace choc
