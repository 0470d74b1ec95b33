// Gauss-Legendre products on boxes and symmetric rules on the triangle and tetrahedron.
#include "fem/Quadrature.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace choc {

namespace {

[[noreturn]] void noSuchRule(const char* cell, int n, const char* available) {
  throw std::invalid_argument(std::string(cell) + " rule with " + std::to_string(n) +
                              " points is not available (" + available + ")");
}

void add(QuadratureRule& q, const Point3& p, double w) {
  q.points.push_back(p);
  q.weights.push_back(w);
}

// The 1D n-point Gauss-Legendre abscissae and weights on [-1, 1].
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  switch (n) {
    case 1:
      x = {0.0};
      w = {2.0};
      return;
    case 2:
      x = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
      w = {1.0, 1.0};
      return;
    case 3:
      x = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
      w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
      return;
  }
  noSuchRule("Gauss-Legendre", n, "1, 2 or 3");
}

QuadratureRule makeBoxRule(int dim, int n) {
  std::vector<double> x, w;
  gaussLegendre(n, x, w);
  QuadratureRule q;
  q.degree = 2 * n - 1;
  const int nj = dim >= 2 ? n : 1, nk = dim == 3 ? n : 1;
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < n; ++i)
        add(q, {x[i], dim >= 2 ? x[j] : 0.0, dim == 3 ? x[k] : 0.0},
            w[i] * (dim >= 2 ? w[j] : 1.0) * (dim == 3 ? w[k] : 1.0));
  return q;
}

// The three points of barycentric coordinates (a, a, 1 - 2a) and its permutations.
void addTriangleOrbit(QuadratureRule& q, double a, double w) {
  const double b = 1 - 2 * a;
  add(q, {a, a, 0}, w);
  add(q, {b, a, 0}, w);
  add(q, {a, b, 0}, w);
}

QuadratureRule makeTriangleRule(int points) {
  QuadratureRule q;
  if (points == 1) {
    q.degree = 1;
    add(q, {1.0 / 3, 1.0 / 3, 0}, 0.5);
  } else if (points == 3) {
    q.degree = 2;
    addTriangleOrbit(q, 1.0 / 6, 1.0 / 6);
  } else if (points == 7) {
    // Radon (1948): centroid weight 9/40, orbits a = (6 -+ sqrt 15)/21 with weights
    // (155 -+ sqrt 15)/1200, all relative to the triangle's area (here 1/2).
    const double s = std::sqrt(15.0);
    q.degree = 5;
    add(q, {1.0 / 3, 1.0 / 3, 0}, 0.5 * 9.0 / 40);
    addTriangleOrbit(q, (6 - s) / 21, 0.5 * (155 - s) / 1200);
    addTriangleOrbit(q, (6 + s) / 21, 0.5 * (155 + s) / 1200);
  } else {
    noSuchRule("triangle", points, "1, 3 or 7");
  }
  return q;
}

// Natural coordinates (xi, eta, zeta) = barycentric (L2, L3, L4) of the point whose
// barycentric coordinates are l (l[0] = L1 = 1 - xi - eta - zeta).
Point3 fromBarycentric(const double l[4]) { return {l[1], l[2], l[3]}; }

// The 4 points with barycentric coordinates (a, a, a, 1 - 3a) permuted.
void addTetOrbit4(QuadratureRule& q, double a, double w) {
  for (int k = 0; k < 4; ++k) {
    double l[4] = {a, a, a, a};
    l[k] = 1 - 3 * a;
    add(q, fromBarycentric(l), w);
  }
}

// The 6 points with barycentric coordinates (a, a, 1/2 - a, 1/2 - a) permuted.
void addTetOrbit6(QuadratureRule& q, double a, double w) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double l[4] = {0.5 - a, 0.5 - a, 0.5 - a, 0.5 - a};
      l[i] = l[j] = a;
      add(q, fromBarycentric(l), w);
    }
}

QuadratureRule makeTetrahedronRule(int points) {
  QuadratureRule q;
  if (points == 1) {
    q.degree = 1;
    add(q, {0.25, 0.25, 0.25}, 1.0 / 6);
  } else if (points == 4) {
    q.degree = 2;
    addTetOrbit4(q, (5 - std::sqrt(5.0)) / 20, 1.0 / 24);
  } else if (points == 14) {
    // The classical positive 14-point degree-5 rule (e.g. Walkington, "Quadrature on
    // simplices of arbitrary dimension", 2000); its exactness is checked by a unit test.
    q.degree = 5;
    addTetOrbit4(q, 0.0927352503108912, 0.01224884051939366);
    addTetOrbit4(q, 0.3108859192633006, 0.01878132095300264);
    addTetOrbit6(q, 0.0455037041256496, 0.007091003462846911);
  } else {
    noSuchRule("tetrahedron", points, "1, 4 or 14");
  }
  return q;
}

}  // namespace

const QuadratureRule& gaussBoxRule(int dim, int n) {
  if (dim < 1 || dim > 3) throw std::invalid_argument("Gauss box rule: dim must be 1, 2 or 3");
  static const std::map<std::pair<int, int>, QuadratureRule> rules = [] {
    std::map<std::pair<int, int>, QuadratureRule> r;
    for (int d = 1; d <= 3; ++d)
      for (int n = 1; n <= 3; ++n) r[{d, n}] = makeBoxRule(d, n);
    return r;
  }();
  const auto it = rules.find({dim, n});
  if (it == rules.end()) noSuchRule("Gauss-Legendre", n, "1, 2 or 3 per direction");
  return it->second;
}

const QuadratureRule& triangleRule(int points) {
  static const QuadratureRule r1 = makeTriangleRule(1), r3 = makeTriangleRule(3),
                              r7 = makeTriangleRule(7);
  if (points == 1) return r1;
  if (points == 3) return r3;
  if (points == 7) return r7;
  noSuchRule("triangle", points, "1, 3 or 7");
}

const QuadratureRule& tetrahedronRule(int points) {
  static const QuadratureRule r1 = makeTetrahedronRule(1), r4 = makeTetrahedronRule(4),
                              r14 = makeTetrahedronRule(14);
  if (points == 1) return r1;
  if (points == 4) return r4;
  if (points == 14) return r14;
  noSuchRule("tetrahedron", points, "1, 4 or 14");
}

}  // namespace choc
