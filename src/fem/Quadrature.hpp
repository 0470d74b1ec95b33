// Quadrature rules on the reference cells of the isoparametric elements. Natural points are
// Point3 with the unused coordinates zero (2D cells use xi, eta). Weights sum to the measure
// of the reference cell: 2^dim on [-1, 1]^dim, 1/2 on the unit triangle, 1/6 on the unit
// tetrahedron. Every rule has positive weights and all its points strictly inside the cell.
#pragma once
#include <vector>

#include "mesh/Mesh.hpp"

namespace choc {

struct QuadratureRule {
  std::vector<Point3> points;
  std::vector<double> weights;
  int degree = 0;  // every polynomial of total (simplex) or per-variable (box) degree <= this
                   // is integrated exactly
  int size() const { return static_cast<int>(points.size()); }
};

// n x ... x n Gauss-Legendre on [-1, 1]^dim (n = 1, 2 or 3; dim = 1, 2 or 3): degree 2n - 1 in
// each variable. Points ordered with xi fastest.
const QuadratureRule& gaussBoxRule(int dim, int n);

// Unit triangle {xi, eta >= 0, xi + eta <= 1}: 1 point (centroid, degree 1), 3 points
// (1/6, 1/6)... (degree 2), 7 points (Radon's rule, degree 5, closed form).
const QuadratureRule& triangleRule(int points);

// Unit tetrahedron {xi, eta, zeta >= 0, sum <= 1}: 1 point (centroid, degree 1), 4 points
// (degree 2), 14 points (degree 5, positive weights: two orbits of 4 points and one of 6).
const QuadratureRule& tetrahedronRule(int points);

}  // namespace choc
