#include "contact/MortarLinearization.hpp"

#include <stdexcept>

#include "contact/MortarIntegration.hpp"

namespace choc {

namespace mortar {

// Linear faces (QUAD4, TRI3, LINE2) in closed form; the others by central differences of step 1
// of the first derivatives, exact for them (a first derivative is at most quadratic in each
// parameter: QUAD8, TRI6, LINE3).
void faceShapesToSecondOrder(const Face& f, double xi, double eta, std::vector<double>& N,
                             std::vector<std::array<double, 2>>& dN, std::vector<std::array<double, 3>>& H) {
  if (f.edgeNodes == 2) {
    N = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    dN = {{{-0.5, 0.0}}, {{0.5, 0.0}}};
    H.assign(2, {0.0, 0.0, 0.0});
    return;
  }
  if (!f.edgeNodes && f.shape == SolidShape::Tri3) {  // barycentric: 1 - xi - eta, xi, eta
    N = {1 - xi - eta, xi, eta};
    dN = {{{-1.0, -1.0}}, {{1.0, 0.0}}, {{0.0, 1.0}}};
    H.assign(3, {0.0, 0.0, 0.0});
    return;
  }
  if (!f.edgeNodes && f.shape == SolidShape::Quad4) {  // N_a = (1 + s_a xi)(1 + t_a eta) / 4
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    N.resize(4);
    dN.resize(4);
    H.resize(4);
    for (size_t a = 0; a < 4; ++a) {
      N[a] = 0.25 * (1 + sx[a] * xi) * (1 + sy[a] * eta);
      dN[a] = {0.25 * sx[a] * (1 + sy[a] * eta), 0.25 * sy[a] * (1 + sx[a] * xi)};
      H[a] = {0.0, 0.25 * sx[a] * sy[a], 0.0};
    }
    return;
  }
  faceShapes(f, xi, eta, N, dN);
  std::vector<double> unused;
  std::vector<std::array<double, 2>> xp, xm, ep, em;
  faceShapes(f, xi + 1, eta, unused, xp);
  faceShapes(f, xi - 1, eta, unused, xm);
  faceShapes(f, xi, eta + 1, unused, ep);
  faceShapes(f, xi, eta - 1, unused, em);
  H.resize(N.size());
  for (size_t a = 0; a < N.size(); ++a)
    H[a] = {0.5 * (xp[a][0] - xm[a][0]), 0.5 * (ep[a][0] - em[a][0]), 0.5 * (ep[a][1] - em[a][1])};
}

}  // namespace mortar

namespace {

using mortar::FaceIn;
using mortar::P3;

// The face's node positions as variables first..first + 3n - 1.
template <class D>
std::vector<P3<D>> seeded(const Face& f, int first) {
  std::vector<P3<D>> x(f.x.size());
  for (size_t a = 0; a < f.x.size(); ++a)
    for (int c = 0; c < 3; ++c) x[a][c] = D::variable(f.x[a][c], first + 3 * int(a) + c);
  return x;
}

// A = D M^-1 of the slave face (MortarSegments.hpp), by Gaussian elimination of M Y = diag(D),
// A = Y^T (M symmetric positive definite: no pivoting).
template <class D>
std::vector<D> dualBasisOf(const FaceIn<D>& s, bool axi) {
  const size_t n = s.face.nodes.size();
  std::vector<D> M, Dg;
  mortar::dualBasisIntegrals(s, axi, M, Dg);
  std::vector<D> Y(n * n, D(0.0));  // row-major n x n
  for (size_t a = 0; a < n; ++a) Y[a * n + a] = Dg[a];
  for (size_t k = 0; k < n; ++k) {
    if (!(M[k * n + k].v > 0)) throw std::invalid_argument("degenerate slave face");
    for (size_t i = k + 1; i < n; ++i) {
      const D f = M[i * n + k] / M[k * n + k];
      for (size_t j = k; j < n; ++j) M[i * n + j] -= f * M[k * n + j];
      for (size_t j = 0; j < n; ++j) Y[i * n + j] -= f * Y[k * n + j];
    }
  }
  for (size_t k = n; k-- > 0;) {
    for (size_t j = k + 1; j < n; ++j)
      for (size_t c = 0; c < n; ++c) Y[k * n + c] -= M[k * n + j] * Y[j * n + c];
    for (size_t c = 0; c < n; ++c) Y[k * n + c] /= M[k * n + k];
  }
  std::vector<D> A(n * n);
  for (size_t a = 0; a < n; ++a)
    for (size_t b = 0; b < n; ++b) A[a * n + b] = Y[b * n + a];
  return A;
}

// The gradient of d by the nodes of the faces its variables stand for (the slave face's first,
// then the master face's from variable 12).
template <class D>
void addGradient(const D& d, const Face& s, const Face* m, NodeGradient& out) {
  for (size_t a = 0; a < s.nodes.size(); ++a) {
    Point3& g = out[s.nodes[a]];
    for (int c = 0; c < 3; ++c) g[c] += d.g[3 * a + size_t(c)];
  }
  for (size_t b = 0; m && b < m->nodes.size(); ++b) {
    Point3& g = out[m->nodes[b]];
    for (int c = 0; c < 3; ++c) g[c] += d.g[12 + 3 * b + size_t(c)];
  }
}

// With N variables: 12 of the slave face (at most 4 nodes), the master face's after them.
template <int N>
OverlapDerivatives derivativesWith(const Face& s, const Face& m, const std::vector<Point3>& nu, bool axi) {
  using D = Dual<N>;
  const std::vector<P3<D>> xs = seeded<D>(s, 0), xm = seeded<D>(m, 12);
  const FaceIn<D> sf{s, xs}, mf{m, xm};
  OverlapDerivatives out;
  const std::vector<mortar::MortarPointOf<D>> pts = mortar::overlapPoints(sf, mf, axi);
  if (pts.empty()) return out;
  const size_t n = s.nodes.size();
  const std::vector<D> A = dualBasisOf(sf, axi);
  std::vector<D> Dsum(n, D(0.0)), Gsum(n, D(0.0));
  out.Gv.assign(n, Point3{0, 0, 0});
  for (const auto& p : pts) {
    const P3<D> gap = mortar::minus(p.xs, p.xm);
    for (size_t a = 0; a < n; ++a) {
      D phi(0.0);
      for (size_t b = 0; b < n; ++b) phi += A[a * n + b] * p.Ns[b];
      const D w = phi * p.weight;
      Dsum[a] += w;
      Gsum[a] += w * (nu[a][0] * gap[0] + nu[a][1] * gap[1] + nu[a][2] * gap[2]);
      for (int c = 0; c < 3; ++c) out.Gv[a][c] += w.v * gap[c].v;
    }
  }
  out.dD.resize(n);
  out.dG.resize(n);
  for (size_t a = 0; a < n; ++a) {
    addGradient(Dsum[a], s, &m, out.dD[a]);
    addGradient(Gsum[a], s, &m, out.dG[a]);
  }
  return out;
}

}  // namespace

OverlapDerivatives overlapDerivatives(const Face& s, const Face& m, const std::vector<Point3>& nu, bool axi) {
  if (s.nodes.size() > 4 || m.nodes.size() > 8) throw std::invalid_argument("mortar faces beyond QUAD4 slaves and QUAD8 masters");
  if (m.nodes.size() <= 4) return derivativesWith<24>(s, m, nu, axi);
  return derivativesWith<36>(s, m, nu, axi);
}

void addNormalDerivative(const Face& f, int a, const Point3& w, NodeGradient& out) {
  using D = Dual<12>;
  const std::vector<P3<D>> x = seeded<D>(f, 0);
  const P3<D> n = mortar::nodeNormalOf(FaceIn<D>{f, x}, a);
  addGradient(w[0] * n[0] + w[1] * n[1] + w[2] * n[2], f, nullptr, out);
}

}  // namespace choc
