// The segment-to-segment integration of MortarSegments.hpp written once for any scalar: double
// (the pairing's values) and Dual (their exact derivatives with respect to the faces' node
// positions, MortarLinearization.hpp). The face's topology comes from a Face, its node
// positions from `x` (for double, the Face's own). The steps, the tolerances and the order of
// the operations are those MortarSegments.hpp describes; a branch (which side of a clipping
// edge, whether a projection converged) is decided on the value.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "contact/ContactFaces.hpp"
#include "core/Dual.hpp"
#include "fem/Quadrature.hpp"

namespace choc {
namespace mortar {

template <class T>
using P3 = std::array<T, 3>;
template <class T>
using P2 = std::array<T, 2>;

template <class T>
T dotOf(const P3<T>& a, const P3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
P3<T> crossOf(const P3<T>& a, const P3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
P3<T> minus(const P3<T>& a, const P3<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class T>
T lengthOf(const P3<T>& v) {
  using std::sqrt;
  return sqrt(dotOf(v, v));
}
template <class T>
P3<T> unitOf(const P3<T>& v) {
  const T l = lengthOf(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}
template <class T>
P3<T> axpy(const P3<T>& x, const T& a, const P3<T>& y) {
  return {x[0] + a * y[0], x[1] + a * y[1], x[2] + a * y[2]};
}

// Position, tangents and shape functions of a face at (xi, eta), in the scalar T.
template <class T>
struct FacePointOf {
  P3<T> x{}, dxi{}, deta{};
  std::vector<T> N;
};

// double: evaluateFace on the Face's own positions (x is f.x).
inline FacePointOf<double> evaluateAt(const Face& f, const std::vector<Point3>&, double xi, double eta) {
  FacePoint p = evaluateFace(f, xi, eta);
  return {p.x, p.dxi, p.deta, std::move(p.N)};
}

// The face's shape functions at (xi, eta), their first derivatives {d/dxi, d/deta} and their
// second ones {d2/dxi2, d2/dxi deta, d2/deta2} (MortarLinearization.cpp).
void faceShapesToSecondOrder(const Face& f, double xi, double eta, std::vector<double>& N,
                             std::vector<std::array<double, 2>>& dN, std::vector<std::array<double, 3>>& H);

// Dual: the shape functions and their derivatives at the parameters' values, carried to the
// parameters' gradients by the chain rule.
template <int N>
FacePointOf<Dual<N>> evaluateAt(const Face& f, const std::vector<P3<Dual<N>>>& x, const Dual<N>& xi,
                                const Dual<N>& eta) {
  std::vector<double> Nv;
  std::vector<std::array<double, 2>> d;
  std::vector<std::array<double, 3>> H;
  faceShapesToSecondOrder(f, xi.v, eta.v, Nv, d, H);
  FacePointOf<Dual<N>> p;
  p.N.resize(Nv.size());
  for (size_t a = 0; a < Nv.size(); ++a) {
    Dual<N> na(Nv[a]), dna(d[a][0]), dea(d[a][1]);
    for (int k = 0; k < N; ++k) {
      na.g[k] = d[a][0] * xi.g[k] + d[a][1] * eta.g[k];
      dna.g[k] = H[a][0] * xi.g[k] + H[a][1] * eta.g[k];
      dea.g[k] = H[a][1] * xi.g[k] + H[a][2] * eta.g[k];
    }
    p.N[a] = na;
    for (int c = 0; c < 3; ++c) {
      p.x[c] += na * x[a][c];
      p.dxi[c] += dna * x[a][c];
      if (!f.edgeNodes) p.deta[c] += dea * x[a][c];
    }
  }
  if (f.edgeNodes) p.deta = {Dual<N>(0.0), Dual<N>(0.0), Dual<N>(1.0)};
  return p;
}

// Both parameters of the face's centre.
inline double centreParameter(const Face& f) { return isTriangle(f) ? 1.0 / 3.0 : 0.0; }
inline int cornersOf(const Face& f) { return f.edgeNodes ? 2 : cornerCount(f.shape); }

// The plane (or line) the overlap is computed in: origin c, unit normal n0, tangents e1, e2.
template <class T>
struct Frame {
  P3<T> c{}, n0{}, e1{}, e2{};
  P2<T> local(const P3<T>& x) const { return {dotOf(minus(x, c), e1), dotOf(minus(x, c), e2)}; }
  P3<T> global(const P2<T>& p) const { return axpy(axpy(c, p[0], e1), p[1], e2); }
};

template <class T>
Frame<T> slaveFrame(const Face& s, const std::vector<P3<T>>& x) {
  Frame<T> fr;
  const double m = centreParameter(s);
  const FacePointOf<T> q = evaluateAt(s, x, T(m), T(m));
  fr.c = q.x;
  fr.n0 = unitOf(crossOf(q.dxi, q.deta));
  fr.e1 = unitOf(q.dxi);
  fr.e2 = crossOf(fr.n0, fr.e1);
  return fr;
}

// One Newton step towards the parameters of the face's point that projects onto X along n0:
// e1, e2 . (x(xi) - X) = 0 (edges: e1 only). False where the step is undefined.
template <class T>
bool projectionStep(const Face& f, const std::vector<P3<T>>& x, const Frame<T>& fr, const P3<T>& X, T& xi, T& eta,
                    T& dx, T& de) {
  using std::abs;
  const FacePointOf<T> q = evaluateAt(f, x, xi, eta);
  const P3<T> d = minus(q.x, X);
  de = T(0.0);
  if (f.edgeNodes) {
    const T a = dotOf(fr.e1, q.dxi);
    if (!(valueOf(abs(a)) > 0)) return false;
    dx = -dotOf(fr.e1, d) / a;
  } else {
    const T a = dotOf(fr.e1, q.dxi), b = dotOf(fr.e1, q.deta), c = dotOf(fr.e2, q.dxi), e = dotOf(fr.e2, q.deta),
            det = a * e - b * c;
    if (!(valueOf(abs(det)) > 0)) return false;
    const T r1 = dotOf(fr.e1, d), r2 = dotOf(fr.e2, d);
    dx = -(e * r1 - b * r2) / det;
    de = -(a * r2 - c * r1) / det;
  }
  xi += dx;
  eta += de;
  return true;
}

// The parameters of the face's point that projects onto X along n0 by Newton from the face's
// centre. False when it does not converge.
inline bool projectAlong(const Face& f, const std::vector<Point3>& x, const Frame<double>& fr, const Point3& X,
                         double& xi, double& eta) {
  xi = eta = centreParameter(f);
  for (int it = 0; it < 30; ++it) {
    double dx, de;
    if (!projectionStep(f, x, fr, X, xi, eta, dx, de)) return false;
    if (std::abs(dx) + std::abs(de) < 1e-12) return true;  // parametric: 1e-12 of the face
  }
  return false;
}

template <int N>
P3<double> valuesOf(const P3<Dual<N>>& p) {
  return {p[0].v, p[1].v, p[2].v};
}

// Dual: the values by Newton in double, then one Newton step in Dual from them, whose gradient
// is the implicit function's (the residual is zero there to the iteration's 1e-12).
template <int N>
bool projectAlong(const Face& f, const std::vector<P3<Dual<N>>>& x, const Frame<Dual<N>>& fr, const P3<Dual<N>>& X,
                  Dual<N>& xi, Dual<N>& eta) {
  std::vector<Point3> xv;
  for (const auto& p : x) xv.push_back(valuesOf(p));
  const Frame<double> fv{valuesOf(fr.c), valuesOf(fr.n0), valuesOf(fr.e1), valuesOf(fr.e2)};
  double xiv, etav;
  if (!projectAlong(f, xv, fv, valuesOf(X), xiv, etav)) return false;
  xi = Dual<N>(xiv);
  eta = Dual<N>(etav);
  Dual<N> dx, de;
  return projectionStep(f, x, fr, X, xi, eta, dx, de);
}

template <class T>
T signedArea(const std::vector<P2<T>>& p) {
  T a(0.0);
  for (size_t i = 0; i < p.size(); ++i) {
    const P2<T>&u = p[i], &v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

// The part of polygon `subject` inside the convex counter-clockwise polygon `clip`. A vertex
// within 1e-12 |b - a| of a clipping edge's line (b - a) counts as on it, inside, and an edge
// is cut only where its ends lie beyond that on either side: matching meshes put vertices on
// the lines, where a cut of two ends at round-off distances would be a 0/0 (its derivative
// 1e13 times the faces' scale).
template <class T>
std::vector<P2<T>> clipPolygon(std::vector<P2<T>> subject, const std::vector<P2<T>>& clip) {
  for (size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const P2<T>&a = clip[i], &b = clip[(i + 1) % clip.size()];
    auto side = [&](const P2<T>& p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    const double ex = valueOf(b[0] - a[0]), ey = valueOf(b[1] - a[1]), tol = 1e-12 * (ex * ex + ey * ey);
    std::vector<P2<T>> out;
    for (size_t k = 0; k < subject.size(); ++k) {
      const P2<T>&p = subject[k], &q = subject[(k + 1) % subject.size()];
      const T sp = side(p), sq = side(q);
      if (valueOf(sp) >= -tol) out.push_back(p);
      if ((valueOf(sp) > tol && valueOf(sq) < -tol) || (valueOf(sp) < -tol && valueOf(sq) > tol)) {
        const T t = sp / (sp - sq);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = out;
  }
  return subject;
}

// The polygon of a face's corners in the frame, counter-clockwise.
template <class T>
std::vector<P2<T>> polygon(const Face& f, const std::vector<P3<T>>& x, const Frame<T>& fr) {
  std::vector<P2<T>> p;
  for (int a = 0; a < cornersOf(f); ++a) p.push_back(fr.local(x[size_t(a)]));
  if (valueOf(signedArea(p)) < 0) std::reverse(p.begin(), p.end());
  return p;
}

template <class T>
struct MortarPointOf {
  std::vector<T> Ns, Nm;  // the slave and master faces' shape functions at the point
  P3<T> xs{}, xm{};       // the point on the slave face, its projection on the master face
  T weight = T(0.0);      // area of the slave surface it stands for [m^2] (rings: 2 pi r)
};

// A face with its node positions in the scalar T.
template <class T>
struct FaceIn {
  const Face& face;
  const std::vector<P3<T>>& x;
};

// Adds the point X (on the frame's plane or line) of weight w (measured there) to `out`, with
// its projections on both faces; false when a projection fails.
template <class T>
bool addPoint(const FaceIn<T>& s, const FaceIn<T>& m, const Frame<T>& fr, const P3<T>& X, const T& w, bool axi,
              std::vector<MortarPointOf<T>>& out) {
  using std::abs;
  T xs, es, xm, em;
  if (!projectAlong(s.face, s.x, fr, X, xs, es) || !projectAlong(m.face, m.x, fr, X, xm, em)) return false;
  const FacePointOf<T> ps = evaluateAt(s.face, s.x, xs, es), pm = evaluateAt(m.face, m.x, xm, em);
  MortarPointOf<T> p;
  p.Ns = ps.N;
  p.Nm = pm.N;
  p.xs = ps.x;
  p.xm = pm.x;
  // dA on the slave surface = dA on the plane / |n . n0|; a ring: times 2 pi r.
  const T cosine = abs(dotOf(unitOf(crossOf(ps.dxi, ps.deta)), fr.n0));
  p.weight = w / cosine * (axi ? T(2.0 * M_PI) * ps.x[0] : T(1.0));
  out.push_back(p);
  return true;
}

// The overlap of two edges: 3-point Gauss on the common interval of the slave edge's line.
template <class T>
std::vector<MortarPointOf<T>> edgePoints(const FaceIn<T>& s, const FaceIn<T>& m, const Frame<T>& fr, bool axi) {
  std::vector<MortarPointOf<T>> out;
  T lo = fr.local(s.x[0])[0], hi = fr.local(s.x[1])[0];
  T a = fr.local(m.x[0])[0], b = fr.local(m.x[1])[0];
  if (lo > hi) std::swap(lo, hi);
  if (a > b) std::swap(a, b);
  const T from = std::max(lo, a), to = std::min(hi, b);
  if (!(valueOf(to - from) > 1e-12 * valueOf(hi - lo))) return out;
  const QuadratureRule& g = gaussBoxRule(1, 3);
  for (int k = 0; k < g.size(); ++k) {
    const T t = 0.5 * (from + to) + 0.5 * (to - from) * g.points[k][0];
    if (!addPoint(s, m, fr, fr.global({t, T(0.0)}), 0.5 * (to - from) * g.weights[k], axi, out)) return {};
  }
  return out;
}

// The integration points of the overlap of slave face s and master face m (MortarSegments.hpp).
template <class T>
std::vector<MortarPointOf<T>> overlapPoints(const FaceIn<T>& s, const FaceIn<T>& m, bool axi) {
  std::vector<MortarPointOf<T>> out;
  const Frame<T> fr = slaveFrame(s.face, s.x);
  const double cm = centreParameter(m.face);
  const FacePointOf<T> mc = evaluateAt(m.face, m.x, T(cm), T(cm));
  if (!(valueOf(dotOf(unitOf(crossOf(mc.dxi, mc.deta)), fr.n0)) < 0)) return out;  // not facing the slave
  if (s.face.edgeNodes) return edgePoints(s, m, fr, axi);
  const std::vector<P2<T>> sp = polygon(s.face, s.x, fr);
  const std::vector<P2<T>> cut = clipPolygon(sp, polygon(m.face, m.x, fr));
  if (cut.size() < 3 || !(valueOf(signedArea(cut)) > 1e-12 * valueOf(signedArea(sp)))) return out;
  const QuadratureRule& r = triangleRule(7);
  for (size_t t = 1; t + 1 < cut.size(); ++t) {
    const P2<T>&a = cut[0], &b = cut[t], &c = cut[t + 1];
    const T twiceArea = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (!(valueOf(twiceArea) > 0)) continue;
    for (int k = 0; k < r.size(); ++k) {
      const double u = r.points[k][0], v = r.points[k][1];
      const P2<T> p{a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]), a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1])};
      if (!addPoint(s, m, fr, fr.global(p), twiceArea * r.weights[k], axi, out)) return {};
    }
  }
  return out;
}

// Natural coordinates of node a of a linear or quadratic face (corners first).
inline std::array<double, 2> nodeParameters(const Face& f, int a) {
  if (f.edgeNodes) return {a == 0 ? -1.0 : a == 1 ? 1.0 : 0.0, 0.0};
  const Point3& p = nodeNaturalCoordinates(f.shape)[size_t(a)];
  return {p[0], p[1]};
}

// The unit outward normal of the face at its node a.
template <class T>
P3<T> nodeNormalOf(const FaceIn<T>& f, int a) {
  const std::array<double, 2> p = nodeParameters(f.face, a);
  const FacePointOf<T> q = evaluateAt(f.face, f.x, T(p[0]), T(p[1]));
  return unitOf(crossOf(q.dxi, q.deta));
}

// D = diag(int N_a) and M_ab = int N_a N_b over the slave face (rings: 2 pi r), for A = D M^-1.
template <class T>
void dualBasisIntegrals(const FaceIn<T>& s, bool axi, std::vector<T>& M, std::vector<T>& D) {
  const size_t n = s.face.nodes.size();
  const QuadratureRule& rule = s.face.edgeNodes ? gaussBoxRule(1, 3) : massRule(s.face.shape);
  M.assign(n * n, T(0.0));
  D.assign(n, T(0.0));
  for (int k = 0; k < rule.size(); ++k) {
    const FacePointOf<T> q = evaluateAt(s.face, s.x, T(rule.points[k][0]), T(rule.points[k][1]));
    const T ring = axi ? T(2.0 * M_PI) * q.x[0] : T(1.0);
    const T J = lengthOf(crossOf(q.dxi, q.deta)) * rule.weights[k] * ring;
    for (size_t a = 0; a < n; ++a) {
      D[a] += q.N[a] * J;
      for (size_t b = 0; b < n; ++b) M[a * n + b] += q.N[a] * q.N[b] * J;
    }
  }
}

}  // namespace mortar
}  // namespace choc
