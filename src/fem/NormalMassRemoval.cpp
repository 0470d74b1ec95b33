// The contact nodes' mass removed along their normals only (fem/NormalMassRemoval.hpp).
#include "fem/NormalMassRemoval.hpp"

#include <limits>
#include <stdexcept>

namespace choc {

namespace {

// The nearest nodes of the element without a direction, with equal weights.
std::vector<int> nearestFree(const std::vector<Point3>& x, const std::vector<const std::vector<Point3>*>& dirs,
                             int k) {
  const int nn = static_cast<int>(x.size());
  double dmin = std::numeric_limits<double>::infinity();
  std::vector<double> d(size_t(nn), dmin);
  for (int j = 0; j < nn; ++j) {
    if (dirs[size_t(j)] && !dirs[size_t(j)]->empty()) continue;
    d[size_t(j)] = 0.0;
    for (int c = 0; c < 3; ++c) d[size_t(j)] += (x[size_t(k)][c] - x[size_t(j)][c]) * (x[size_t(k)][c] - x[size_t(j)][c]);
    dmin = std::min(dmin, d[size_t(j)]);
  }
  if (!(dmin < std::numeric_limits<double>::infinity()))
    throw std::invalid_argument(
        "every node of an element lies on a contact surface: its normal mass cannot be moved onto another "
        "node (refine the mesh so that each element touching a contact surface has a node off it)");
  std::vector<int> out;
  for (int j = 0; j < nn; ++j)
    if (d[size_t(j)] <= dmin * (1 + 1e-8)) out.push_back(j);
  return out;
}

// T (n x n, node-major): identity but for the contact nodes' rows.
DenseMatrix transform(const std::vector<Point3>& x, const std::vector<const std::vector<Point3>*>& dirs,
                      const std::vector<int>& comps) {
  const int nn = static_cast<int>(x.size()), nc = static_cast<int>(comps.size());
  DenseMatrix T(nn * nc, nn * nc);
  for (int k = 0; k < nn; ++k) {
    const bool constrained = dirs[size_t(k)] && !dirs[size_t(k)]->empty();
    if (!constrained) {
      for (int c = 0; c < nc; ++c) T(k * nc + c, k * nc + c) = 1.0;
      continue;
    }
    DenseMatrix N(nc, nc);
    for (const Point3& d : *dirs[size_t(k)])
      for (int c = 0; c < nc; ++c)
        for (int e = 0; e < nc; ++e) N(c, e) += d[size_t(comps[size_t(c)])] * d[size_t(comps[size_t(e)])];
    const std::vector<int> to = nearestFree(x, dirs, k);
    const double w = 1.0 / double(to.size());
    for (int c = 0; c < nc; ++c)
      for (int e = 0; e < nc; ++e) {
        T(k * nc + c, k * nc + e) = (c == e ? 1.0 : 0.0) - N(c, e);
        for (int j : to) T(k * nc + c, j * nc + e) += w * N(c, e);
      }
  }
  return T;
}

}  // namespace

void removeNormalMass(const std::vector<Point3>& x, const std::vector<const std::vector<Point3>*>& directions,
                      const std::vector<int>& comps, MassKind kind, DenseMatrix& Me) {
  bool any = false;
  for (const auto* d : directions) any = any || (d && !d->empty());
  if (!any) return;
  const int nc = static_cast<int>(comps.size()), n = Me.rows();
  const DenseMatrix T = transform(x, directions, comps);
  DenseMatrix R(n, n), out(n, n);  // R = Me T, out = T^T R
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < n; ++l) {
      const double m = Me(i, l);
      if (m != 0.0)
        for (int b = 0; b < n; ++b) R(i, b) += m * T(l, b);
    }
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < n; ++a) {
      const double t = T(i, a);
      if (t != 0.0)
        for (int b = 0; b < n; ++b) out(a, b) += t * R(i, b);
    }
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) Me(a, b) = kind == MassKind::Lumped ? 0.0 : 0.5 * (out(a, b) + out(b, a));
  if (kind != MassKind::Lumped) return;
  // Lumped again by node blocks: entry (a, b) moves to (a, b's component at a's node).
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) Me(a, (a / nc) * nc + b % nc) += 0.5 * (out(a, b) + out(b, a));
  for (int a = 0; a < n; ++a)  // each node's block symmetric (P N = 0 up to round-off)
    for (int b = (a / nc) * nc; b < a; ++b) Me(a, b) = Me(b, a) = 0.5 * (Me(a, b) + Me(b, a));
}

}  // namespace choc
