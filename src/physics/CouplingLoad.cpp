#include "physics/CouplingLoad.hpp"

#include <cmath>
#include <stdexcept>

#include "materials/Tensor2.hpp"

namespace choc {

namespace {

// [v]x, the matrix of v x (.).
Mat3 crossOf(const Vec3& v) { return {{{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}}}; }

Vec3 times(const Mat3& A, const Vec3& x) {
  return {A[0][0] * x[0] + A[0][1] * x[1] + A[0][2] * x[2], A[1][0] * x[0] + A[1][1] * x[1] + A[1][2] * x[2],
          A[2][0] * x[0] + A[2][1] * x[1] + A[2][2] * x[2]};
}

}  // namespace

void couplingForce(const std::vector<Point3>& x, const Vec3& F, const Vec3& M, std::vector<double>& f,
                   DenseMatrix* K) {
  const size_t n = x.size();
  f.assign(3 * n, 0.0);
  if (K) K->resize(int(3 * n), int(3 * n));
  Vec3 c{};
  for (const Point3& p : x)
    for (int d = 0; d < 3; ++d) c[size_t(d)] += p[size_t(d)] / double(n);
  std::vector<Vec3> r(n);
  Mat3 J{};
  double scale = 0.0;
  for (size_t i = 0; i < n; ++i) {
    r[i] = x[i] - c;
    const double rr = dot(r[i], r[i]);
    scale += rr;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) J[size_t(a)][size_t(b)] += (a == b ? rr : 0.0) - r[i][size_t(a)] * r[i][size_t(b)];
  }
  Vec3 a{};
  Mat3 Jinv{};
  const bool moment = M[0] != 0.0 || M[1] != 0.0 || M[2] != 0.0;
  if (moment) {
    const double det = determinant(J);
    if (!(std::abs(det) > 1e-12 * scale * scale * scale))
      throw std::invalid_argument("its nodes lie on one line: a moment cannot be spread over them");
    Jinv = inverse(J, det);
    a = times(Jinv, M);
  }
  for (size_t i = 0; i < n; ++i) {
    const Vec3 ar = cross(a, r[i]);
    for (int d = 0; d < 3; ++d) f[3 * i + size_t(d)] = F[size_t(d)] / double(n) + ar[size_t(d)];
  }
  if (!K || !moment) return;
  const Mat3 A = crossOf(a);
  for (size_t k = 0; k < n; ++k) {
    // J^-1 B_k
    Mat3 B{};
    const double ra = dot(r[k], a);
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
        B[size_t(p)][size_t(q)] = 2 * a[size_t(p)] * r[k][size_t(q)] - (p == q ? ra : 0.0) - r[k][size_t(p)] * a[size_t(q)];
    const Mat3 JB = multiply(Jinv, B);
    for (size_t i = 0; i < n; ++i) {
      const Mat3 RJB = multiply(crossOf(r[i]), JB);
      const double shift = (i == k ? 1.0 : 0.0) - 1.0 / double(n);
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q)
          (*K)(int(3 * i) + p, int(3 * k) + q) = A[size_t(p)][size_t(q)] * shift + RJB[size_t(p)][size_t(q)];
    }
  }
}

CouplingLoad::CouplingLoad(std::string name, const std::vector<int>& nodes, const Mesh& mesh, Vec3 force, Vec3 moment,
                           double rampTime, const DofMap& dofs, int components, const CrsMatrix& K)
    : StateLoad(std::move(name), rampTime, dofs, components, K), force_(force), moment_(moment) {
  std::vector<Point3> X;
  for (int node : nodes) X.push_back(mesh.coords[size_t(node)]);
  addGroup(nodes, std::move(X), 0);
}

void CouplingLoad::groupForce(const Group&, const std::vector<Point3>& x, std::vector<double>& f, DenseMatrix* K) const {
  couplingForce(x, force_, moment_, f, K);
}

}  // namespace choc
