#include "contact/ContactFaces.hpp"

#include <cmath>

#include "mesh/Topology.hpp"

namespace choc {

namespace {

bool faceShape(size_t nodes, const std::string& sideTopology, SolidShape& shape) {
  if (sideTopology == "QUAD4" && nodes == 4) shape = SolidShape::Quad4;
  else if (sideTopology == "QUAD8" && nodes == 8) shape = SolidShape::Quad8;
  else if (sideTopology == "TRI3" && nodes == 3) shape = SolidShape::Tri3;
  else if (sideTopology == "TRI6" && nodes == 6) shape = SolidShape::Tri6;
  else return false;
  return true;
}

// The shape functions of an edge at xi in [-1, 1] and their derivatives: LINE2 linear; LINE3
// quadratic with its mid node third (Exodus).
void edgeShapes(const Face& f, double xi, std::vector<double>& N, std::vector<double>& dN) {
  if (f.edgeNodes == 2) {
    N = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    dN = {-0.5, 0.5};
  } else {
    N = {0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi};
    dN = {xi - 0.5, xi + 0.5, -2 * xi};
  }
}

FacePoint evaluateEdge(const Face& f, double xi) {
  FacePoint p;
  std::vector<double> dN;
  edgeShapes(f, xi, p.N, dN);
  for (size_t a = 0; a < f.x.size(); ++a)
    for (int d = 0; d < 3; ++d) {
      p.x[d] += p.N[a] * f.x[a][d];
      p.dxi[d] += dN[a] * f.x[a][d];
    }
  p.deta = {0.0, 0.0, 1.0};
  return p;
}

// Closest point of x on a surface patch by Gauss-Newton on its parameters from (xi, eta);
// `at(xi, eta)` gives the position and tangents there.
template <class Evaluate>
bool gaussNewtonProjection(const Evaluate& at, const Point3& x, double& xi, double& eta) {
  for (int it = 0; it < 30; ++it) {
    const auto q = at(xi, eta);
    const Point3 d = q.x - x;
    const double r1 = dot(q.dxi, d), r2 = dot(q.deta, d);
    const double a = dot(q.dxi, q.dxi), b = dot(q.dxi, q.deta), e = dot(q.deta, q.deta);
    const double det = a * e - b * b;
    if (!(det > 0)) return false;
    const double dxi = -(e * r1 - b * r2) / det, deta = -(a * r2 - b * r1) / det;
    xi += dxi;
    eta += deta;
    if (std::abs(dxi) + std::abs(deta) < 1e-13) return true;
  }
  return false;
}

}  // namespace

std::vector<Face> facesOf(const Mesh& mesh, const std::string& name) {
  const SideSet* ss = mesh.findSideSet(name);
  if (!ss) {
    std::string all;
    for (const auto& n : mesh.sideSetNames()) all += (all.empty() ? "" : ", ") + n;
    throw std::invalid_argument("no side set '" + name + "' in the mesh (side sets: " +
                                (all.empty() ? "none" : all) + ")");
  }
  std::vector<Face> faces;
  for (size_t k = 0; k < ss->elements.size(); ++k) {
    Face f;
    f.nodes = mesh.sideNodes(ss->elements[k], ss->sides[k]);
    const ElementBlock& b = mesh.blocks[mesh.locateElement(ss->elements[k]).first];
    const Topology* t = findTopology(b.topology);
    const std::string sideTopo = t ? t->sideTopologies[ss->sides[k] - 1] : "";
    if ((sideTopo == "LINE2" && f.nodes.size() == 2) || (sideTopo == "LINE3" && f.nodes.size() == 3))
      f.edgeNodes = static_cast<int>(f.nodes.size());
    else if (!t || !faceShape(f.nodes.size(), sideTopo, f.shape))
      throw std::invalid_argument("side set '" + name + "' has a side of a " + b.topology +
                                  " element: contact needs faces of solids (QUAD4, QUAD8, TRI3, "
                                  "TRI6) or edges of planar elements (LINE2, LINE3)");
    for (int n : f.nodes) f.x.push_back(mesh.coords[n]);
    faces.push_back(f);
  }
  if (faces.empty()) throw std::invalid_argument("side set '" + name + "' is empty");
  return faces;
}


FacePoint evaluateFace(const Face& f, double xi, double eta) {
  if (f.edgeNodes) return evaluateEdge(f, xi);
  FacePoint p;
  if (f.shape == SolidShape::Quad4) {
    const QuadPoint q = evaluateQuad({f.x[0], f.x[1], f.x[2], f.x[3]}, xi, eta);
    p.x = q.x;
    p.dxi = q.dxi;
    p.deta = q.deta;
    p.N.assign(q.N.begin(), q.N.end());
    return p;
  }
  std::vector<Point3> dN;
  shapeFunctions(f.shape, Point3{xi, eta, 0.0}, p.N, dN);
  for (size_t a = 0; a < f.x.size(); ++a)
    for (int d = 0; d < 3; ++d) {
      p.x[d] += p.N[a] * f.x[a][d];
      p.dxi[d] += dN[a][0] * f.x[a][d];
      p.deta[d] += dN[a][1] * f.x[a][d];
    }
  return p;
}

void faceShapes(const Face& f, double xi, double eta, std::vector<double>& N, std::vector<std::array<double, 2>>& dN) {
  if (f.edgeNodes) {
    std::vector<double> d;
    edgeShapes(f, xi, N, d);
    dN.resize(d.size());
    for (size_t a = 0; a < d.size(); ++a) dN[a] = {d[a], 0.0};
    return;
  }
  std::vector<Point3> d;
  shapeFunctions(f.shape, Point3{xi, eta, 0.0}, N, d);
  dN.resize(d.size());
  for (size_t a = 0; a < d.size(); ++a) dN[a] = {d[a][0], d[a][1]};
}

bool isTriangle(const Face& f) {
  return !f.edgeNodes && (f.shape == SolidShape::Tri3 || f.shape == SolidShape::Tri6);
}

QuadPoint evaluateQuad(const std::array<Point3, 4>& c, double xi, double eta) {
  static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  QuadPoint q;
  for (int i = 0; i < 4; ++i) {
    q.N[i] = 0.25 * (1 + sx[i] * xi) * (1 + sy[i] * eta);
    const double dNx = 0.25 * sx[i] * (1 + sy[i] * eta), dNy = 0.25 * sy[i] * (1 + sx[i] * xi);
    for (int d = 0; d < 3; ++d) {
      q.x[d] += q.N[i] * c[i][d];
      q.dxi[d] += dNx * c[i][d];
      q.deta[d] += dNy * c[i][d];
    }
  }
  return q;
}


bool projectOnQuad(const std::array<Point3, 4>& c, const Point3& x, double& xi, double& eta) {
  xi = eta = 0.0;
  return gaussNewtonProjection([&](double s, double t) { return evaluateQuad(c, s, t); }, x, xi, eta);
}

// Closest point of x on the face from the face's centre.
bool projectOnFace(const Face& f, const Point3& x, double& xi, double& eta) {
  if (!f.edgeNodes && f.shape == SolidShape::Quad4)
    return projectOnQuad({f.x[0], f.x[1], f.x[2], f.x[3]}, x, xi, eta);
  xi = eta = isTriangle(f) ? 1.0 / 3.0 : 0.0;
  return gaussNewtonProjection([&](double s, double t) { return evaluateFace(f, s, t); }, x, xi, eta);
}

bool insideFace(const Face& f, double xi, double eta, double tol) {
  if (f.edgeNodes) return std::abs(xi) <= 1.0 + tol;
  if (isTriangle(f)) return xi >= -tol && eta >= -tol && xi + eta <= 1.0 + tol;
  return std::abs(xi) <= 1.0 + tol && std::abs(eta) <= 1.0 + tol;
}

}  // namespace choc
