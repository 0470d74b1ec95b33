// Pressures on the current faces, with their load stiffness (header).
#include "physics/FollowerPressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/DofMap.hpp"
#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"
#include "physics/Loads.hpp"

namespace choc {
namespace {

// Shape functions of a face or edge and their derivatives along xi and eta.
void faceShape(const Face& f, double xi, double eta, std::vector<double>& N, std::vector<std::array<double, 2>>& dN) {
  if (f.edgeNodes == 2) {
    N = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    dN = {{{-0.5, 0.0}}, {{0.5, 0.0}}};
    return;
  }
  if (f.edgeNodes == 3) {
    N = {0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi};
    dN = {{{xi - 0.5, 0.0}}, {{xi + 0.5, 0.0}}, {{-2 * xi, 0.0}}};
    return;
  }
  std::vector<Point3> d;
  shapeFunctions(f.shape, Point3{xi, eta, 0.0}, N, d);
  dN.resize(d.size());
  for (size_t a = 0; a < d.size(); ++a) dN[a] = {d[a][0], d[a][1]};
}

// [a]x b = a x b: the cross-product matrix's entry (i, j).
double crossMatrix(const Point3& a, int i, int j) {
  static const int eps[3][3][3] = {{{0, 0, 0}, {0, 0, 1}, {0, -1, 0}},
                                   {{0, 0, -1}, {0, 0, 0}, {1, 0, 0}},
                                   {{0, 1, 0}, {-1, 0, 0}, {0, 0, 0}}};
  double s = 0.0;
  for (int k = 0; k < 3; ++k) s += eps[i][k][j] * a[k];
  return s;
}

const QuadratureRule& faceRule(const Face& f) { return f.edgeNodes ? gaussBoxRule(1, 3) : massRule(f.shape); }

}  // namespace

void followerFaceForce(const Face& face, const PressureField& p, const std::vector<Point3>& x, bool axisymmetric,
                       std::vector<double>& force, DenseMatrix* K) {
  const int n = static_cast<int>(face.nodes.size());
  force.assign(size_t(3 * n), 0.0);
  if (K) K->resize(3 * n, 3 * n);
  const QuadratureRule& rule = faceRule(face);
  std::vector<double> N;
  std::vector<std::array<double, 2>> dN;
  for (int q = 0; q < rule.size(); ++q) {
    faceShape(face, rule.points[q][0], rule.points[q][1], N, dN);
    Point3 X{}, xq{}, t1{}, t2{};
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) {
        X[d] += N[a] * face.x[a][d];
        xq[d] += N[a] * x[a][d];
        t1[d] += dN[a][0] * x[a][d];
        t2[d] += dN[a][1] * x[a][d];
      }
    if (face.edgeNodes) t2 = {0.0, 0.0, 1.0};
    const double ring = axisymmetric && face.edgeNodes ? 2.0 * M_PI * xq[0] : 1.0;
    const Point3 nA = cross(t1, t2);  // outward normal times the area element (current)
    const double w = -p.at(X) * rule.weights[q];
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) force[size_t(3 * a + i)] += w * ring * N[a] * nA[i];
    if (!K) continue;
    // d nA / d x_b = dN_b/dxi [e_j x t2] + dN_b/deta [t1 x e_j] = -dN_b/dxi [t2]x + dN_b/deta [t1]x
    for (int b = 0; b < n; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double dn = -dN[b][0] * crossMatrix(t2, i, j);
          if (!face.edgeNodes) dn += dN[b][1] * crossMatrix(t1, i, j);
          double d = ring * dn;
          if (axisymmetric && face.edgeNodes && j == 0) d += 2.0 * M_PI * N[b] * nA[i];
          for (int a = 0; a < n; ++a) (*K)(3 * a + i, 3 * b + j) += w * N[a] * d;
        }
  }
}

FollowerPressure::FollowerPressure(std::string name, std::vector<Face> faces, PressureField p, double rampTime,
                                   bool axisymmetric, const DofMap& dofs, int components, const CrsMatrix& K)
    : StateLoad(std::move(name), rampTime, dofs, components, K), p_(p), axisymmetric_(axisymmetric),
      faces_(std::move(faces)) {
  for (size_t k = 0; k < faces_.size(); ++k) addGroup(faces_[k].nodes, faces_[k].x, k);
}

void FollowerPressure::groupForce(const Group& g, const std::vector<Point3>& x, std::vector<double>& f,
                                  DenseMatrix* K) const {
  followerFaceForce(faces_[g.index], p_, x, axisymmetric_, f, K);
}

}  // namespace choc
