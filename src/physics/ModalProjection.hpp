// Projection of a physical field on a modal basis: mass-weighted (q = Phi^T M u, exact for
// an M-orthonormal basis when u lies in its span) or least squares (Phi^T Phi q = Phi^T u).
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

std::vector<double> projectOnBasis(const MultiVector& Phi, const CrsMatrix& M, const Vector& u,
                                   const std::string& method);
// u = Phi q.
void expandOnBasis(const MultiVector& Phi, const std::vector<double>& q, Vector& u);
// ||u - Phi q|| / ||u|| (0 when u = 0).
double projectionResidual(const MultiVector& Phi, const Vector& u, const std::vector<double>& q);

}  // namespace choc
