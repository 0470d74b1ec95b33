// Diagonal (lumped) masses from a consistent scalar mass matrix m_ab = int rho N_a N_b dV.
#pragma once
#include <cstddef>  // size_t, used by DenseMatrix.hpp
#include <vector>

#include "fem/DenseMatrix.hpp"

namespace choc {

// Row sums: l_a = sum_b m_ab = int rho N_a dV. Positive for linear elements (N_a >= 0);
// zero or negative at the corners of TET10 and HEX20.
std::vector<double> rowSumLumping(const DenseMatrix& m);

// Hinton-Rock-Zienkiewicz: l_a = m_aa * (sum_ab m_ab) / (sum_c m_cc). Positive whenever the
// consistent matrix is positive definite; keeps the element mass. All zero for a zero mass.
std::vector<double> hrzLumping(const DenseMatrix& m);

}  // namespace choc
