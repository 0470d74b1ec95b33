#include "contact/MortarSegments.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Teuchos_LAPACK.hpp>

#include "fem/Quadrature.hpp"

namespace choc {

namespace {

using Point2 = std::array<double, 2>;

Point3 unit(const Point3& v) {
  const double l = norm(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}

Point3 axpy(const Point3& x, double a, const Point3& y) {
  return {x[0] + a * y[0], x[1] + a * y[1], x[2] + a * y[2]};
}

// Natural coordinates of node a of a linear or quadratic face (corners first).
std::array<double, 2> nodeParameters(const Face& f, int a) {
  if (f.edgeNodes) return {a == 0 ? -1.0 : a == 1 ? 1.0 : 0.0, 0.0};
  const Point3& p = nodeNaturalCoordinates(f.shape)[a];
  return {p[0], p[1]};
}

int corners(const Face& f) { return f.edgeNodes ? 2 : cornerCount(f.shape); }

// Both parameters of the face's centre.
double centreParameter(const Face& f) { return isTriangle(f) ? 1.0 / 3.0 : 0.0; }

Point3 faceNormal(const Face& f, double xi, double eta) {
  const FacePoint q = evaluateFace(f, xi, eta);
  return unit(cross(q.dxi, q.deta));
}

// The plane (or line) the overlap is computed in: origin c, unit normal n0, tangents e1, e2.
struct Frame {
  Point3 c{}, n0{}, e1{}, e2{};
  Point2 local(const Point3& x) const { return {dot(x - c, e1), dot(x - c, e2)}; }
  Point3 global(const Point2& p) const { return axpy(axpy(c, p[0], e1), p[1], e2); }
};

Frame slaveFrame(const Face& s) {
  Frame fr;
  const double m = centreParameter(s);
  const FacePoint q = evaluateFace(s, m, m);
  fr.c = q.x;
  fr.n0 = unit(cross(q.dxi, q.deta));
  fr.e1 = unit(q.dxi);
  fr.e2 = cross(fr.n0, fr.e1);
  return fr;
}

// Parameters of the face's point that projects onto X along n0: e1, e2 . (x(xi) - X) = 0
// (edges: e1 only). False when Newton does not converge.
bool projectAlong(const Face& f, const Frame& fr, const Point3& X, double& xi, double& eta) {
  xi = eta = centreParameter(f);
  for (int it = 0; it < 30; ++it) {
    const FacePoint q = evaluateFace(f, xi, eta);
    const Point3 d = q.x - X;
    double dx, de = 0;
    if (f.edgeNodes) {
      const double a = dot(fr.e1, q.dxi);
      if (!(std::abs(a) > 0)) return false;
      dx = -dot(fr.e1, d) / a;
    } else {
      const double a = dot(fr.e1, q.dxi), b = dot(fr.e1, q.deta), c = dot(fr.e2, q.dxi),
                   e = dot(fr.e2, q.deta), det = a * e - b * c;
      if (!(std::abs(det) > 0)) return false;
      const double r1 = dot(fr.e1, d), r2 = dot(fr.e2, d);
      dx = -(e * r1 - b * r2) / det;
      de = -(a * r2 - c * r1) / det;
    }
    xi += dx;
    eta += de;
    if (std::abs(dx) + std::abs(de) < 1e-12) return true;  // parametric: 1e-12 of the face
  }
  return false;
}

double signedArea(const std::vector<Point2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Point2 &u = p[i], &v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

// The part of polygon `subject` inside the convex counter-clockwise polygon `clip`.
std::vector<Point2> clipPolygon(std::vector<Point2> subject, const std::vector<Point2>& clip) {
  for (size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Point2 &a = clip[i], &b = clip[(i + 1) % clip.size()];
    auto side = [&](const Point2& p) { return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]); };
    std::vector<Point2> out;
    for (size_t k = 0; k < subject.size(); ++k) {
      const Point2 &p = subject[k], &q = subject[(k + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double t = sp / (sp - sq);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = out;
  }
  return subject;
}

// The polygon of a face's corners in the frame, counter-clockwise.
std::vector<Point2> polygon(const Face& f, const Frame& fr) {
  std::vector<Point2> p;
  for (int a = 0; a < corners(f); ++a) p.push_back(fr.local(f.x[a]));
  if (signedArea(p) < 0) std::reverse(p.begin(), p.end());
  return p;
}

// Adds the point X (on the frame's plane or line) of weight w (measured there) to `out`, with
// its projections on both faces; false when a projection fails.
bool addPoint(const Face& s, const Face& m, const Frame& fr, const Point3& X, double w, bool axi,
              std::vector<MortarPoint>& out) {
  double xs, es, xm, em;
  if (!projectAlong(s, fr, X, xs, es) || !projectAlong(m, fr, X, xm, em)) return false;
  const FacePoint ps = evaluateFace(s, xs, es), pm = evaluateFace(m, xm, em);
  MortarPoint p;
  p.Ns = ps.N;
  p.Nm = pm.N;
  p.xs = ps.x;
  p.xm = pm.x;
  // dA on the slave surface = dA on the plane / |n . n0|; a ring: times 2 pi r.
  const double cosine = std::abs(dot(unit(cross(ps.dxi, ps.deta)), fr.n0));
  p.weight = w / cosine * (axi ? 2.0 * M_PI * ps.x[0] : 1.0);
  out.push_back(p);
  return true;
}

}  // namespace

bool mortarSlaveFace(const Face& f) {
  return f.edgeNodes ? f.edgeNodes == 2 : f.shape == SolidShape::Tri3 || f.shape == SolidShape::Quad4;
}

Point3 nodeNormal(const Face& f, int a) {
  const auto p = nodeParameters(f, a);
  return faceNormal(f, p[0], p[1]);
}

DenseMatrix dualBasis(const Face& s, bool axisymmetric) {
  if (!mortarSlaveFace(s))
    throw std::invalid_argument("mortar takes TRI3, QUAD4 and LINE2 slave faces");
  const int n = static_cast<int>(s.nodes.size());
  const QuadratureRule& rule = s.edgeNodes ? gaussBoxRule(1, 3) : massRule(s.shape);
  DenseMatrix M(n, n);
  std::vector<double> D(n, 0.0);
  for (int k = 0; k < rule.size(); ++k) {
    const FacePoint q = evaluateFace(s, rule.points[k][0], rule.points[k][1]);
    const double ring = axisymmetric ? 2.0 * M_PI * q.x[0] : 1.0;
    const double J = norm(cross(q.dxi, q.deta)) * rule.weights[k] * ring;
    for (int a = 0; a < n; ++a) {
      D[a] += q.N[a] * J;
      for (int b = 0; b < n; ++b) M(a, b) += q.N[a] * q.N[b] * J;
    }
  }
  // A = D M^-1; M symmetric positive definite: A^T = M^-1 D by Cholesky (column-major Y = A^T).
  std::vector<double> Mc(size_t(n) * n), Y(size_t(n) * n, 0.0);
  for (int a = 0; a < n; ++a) {
    Y[size_t(a) * n + a] = D[a];
    for (int b = 0; b < n; ++b) Mc[size_t(b) * n + a] = M(a, b);
  }
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.POSV('L', n, n, Mc.data(), n, Y.data(), n, &info);
  if (info != 0) throw std::invalid_argument("degenerate slave face");
  DenseMatrix A(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) A(a, b) = Y[size_t(a) * n + b];  // A(a, b) = Y(b, a)
  return A;
}

std::vector<double> dualShapes(const DenseMatrix& A, const std::vector<double>& N) {
  std::vector<double> phi(A.rows(), 0.0);
  for (int a = 0; a < A.rows(); ++a)
    for (int b = 0; b < A.cols(); ++b) phi[a] += A(a, b) * N[b];
  return phi;
}

std::vector<MortarPoint> mortarPoints(const Face& s, const Face& m, bool axisymmetric) {
  std::vector<MortarPoint> out;
  const Frame fr = slaveFrame(s);
  if (!(dot(faceNormal(m, centreParameter(m), centreParameter(m)), fr.n0) < 0))
    return out;  // the master face does not face the slave
  if (s.edgeNodes) {  // intervals on the slave edge's line
    double lo = fr.local(s.x[0])[0], hi = fr.local(s.x[1])[0];
    double a = fr.local(m.x[0])[0], b = fr.local(m.x[1])[0];
    if (lo > hi) std::swap(lo, hi);
    if (a > b) std::swap(a, b);
    const double from = std::max(lo, a), to = std::min(hi, b);
    if (!(to - from > 1e-12 * (hi - lo))) return out;
    const QuadratureRule& g = gaussBoxRule(1, 3);
    for (int k = 0; k < g.size(); ++k) {
      const double t = 0.5 * (from + to) + 0.5 * (to - from) * g.points[k][0];
      if (!addPoint(s, m, fr, fr.global({t, 0.0}), 0.5 * (to - from) * g.weights[k], axisymmetric, out))
        return {};
    }
    return out;
  }
  const std::vector<Point2> sp = polygon(s, fr);
  const std::vector<Point2> cut = clipPolygon(sp, polygon(m, fr));
  if (cut.size() < 3 || !(signedArea(cut) > 1e-12 * signedArea(sp))) return out;
  const QuadratureRule& r = triangleRule(7);
  for (size_t t = 1; t + 1 < cut.size(); ++t) {
    const Point2 &a = cut[0], &b = cut[t], &c = cut[t + 1];
    const double twiceArea = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (!(twiceArea > 0)) continue;
    for (int k = 0; k < r.size(); ++k) {
      const double u = r.points[k][0], v = r.points[k][1];
      const Point2 p{a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]), a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1])};
      if (!addPoint(s, m, fr, fr.global(p), twiceArea * r.weights[k], axisymmetric, out)) return {};
    }
  }
  return out;
}

}  // namespace choc
