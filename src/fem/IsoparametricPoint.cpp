// Jacobian J(i, j) = dx_j/dxi_i of the isoparametric map, its determinant and inverse.
#include "fem/IsoparametricPoint.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace choc {

namespace {

using Matrix3 = double[3][3];

double determinant(int dim, const Matrix3 J) {
  if (dim == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// inv(J) by cofactors (det > 0).
void inverse(int dim, const Matrix3 J, double det, Matrix3 Ji) {
  if (dim == 2) {
    Ji[0][0] = J[1][1] / det;
    Ji[0][1] = -J[0][1] / det;
    Ji[1][0] = -J[1][0] / det;
    Ji[1][1] = J[0][0] / det;
    return;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // Ji(i, j) = cofactor(j, i) / det, cyclic indices give the signs.
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      Ji[i][j] = (J[j1][i1] * J[j2][i2] - J[j1][i2] * J[j2][i1]) / det;
    }
}

// Fills p.N, p.x, dN/dxi and J; returns det J.
double jacobian(SolidShape t, const std::vector<Point3>& x, const Point3& xi, IsoparametricPoint& p,
                std::vector<Point3>& dN, Matrix3 J) {
  const int n = nodeCount(t), dim = parametricDimension(t);
  if (static_cast<int>(x.size()) != n)
    throw std::invalid_argument(std::string(topologyName(t)) + ": expected " + std::to_string(n) +
                                " node coordinates, got " + std::to_string(x.size()));
  shapeFunctions(t, xi, p.N, dN);
  p.x = {0, 0, 0};
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < dim; ++j) {
      p.x[j] += p.N[a] * x[a][j];
      for (int i = 0; i < dim; ++i) J[i][j] += dN[a][i] * x[a][j];
    }
  return determinant(dim, J);
}

}  // namespace

void throwInverted(SolidShape t, double det, const Point3& xi) {
  std::ostringstream msg;
  msg << "inverted or degenerate " << topologyName(t) << " element: Jacobian determinant " << det
      << " <= 0 at natural point " << naturalPointText(t, xi)
      << "; check the node order against the Exodus II convention";
  throw std::invalid_argument(msg.str());
}

std::string naturalPointText(SolidShape t, const Point3& xi) {
  std::ostringstream s;
  s << "(" << xi[0] << ", " << xi[1];
  if (parametricDimension(t) == 3) s << ", " << xi[2];
  s << ")";
  return s.str();
}

double jacobianDeterminant(SolidShape t, const std::vector<Point3>& x, const Point3& xi) {
  IsoparametricPoint p;
  std::vector<Point3> dN;
  Matrix3 J = {};
  return jacobian(t, x, xi, p, dN, J);
}

void evaluateIsoparametric(SolidShape t, const std::vector<Point3>& x, const Point3& xi,
                           IsoparametricPoint& p) {
  std::vector<Point3> dN;
  Matrix3 J = {};
  const int n = nodeCount(t), dim = parametricDimension(t);
  p.detJ = jacobian(t, x, xi, p, dN, J);
  if (!(p.detJ > 0.0)) throwInverted(t, p.detJ, xi);
  Matrix3 Ji = {};
  inverse(dim, J, p.detJ, Ji);
  p.dNdx.assign(n, {0, 0, 0});
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < dim; ++j)
      for (int i = 0; i < dim; ++i) p.dNdx[a][j] += Ji[j][i] * dN[a][i];
}

}  // namespace choc
