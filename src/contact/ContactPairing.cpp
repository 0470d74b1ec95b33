#include "contact/ContactPairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "fem/DenseMatrix.hpp"
#include "fem/MassLumping.hpp"
#include "fem/ShapeFunctions.hpp"
#include "mesh/Topology.hpp"

namespace choc {

namespace {


// A face of a solid: its nodes, their positions, its shape (QUAD4: the bilinear code below,
// kept as it was; the others through the isoparametric library).
// An edge of a planar element (2D meshes, in the x-y plane) is a "face" with one parameter:
// its second tangent is e_z, so that dxi x e_z is the outward normal of a counter-clockwise
// element and |dxi x e_z| the length element.
struct Face {
  std::vector<int> nodes;
  std::vector<Point3> x;
  SolidShape shape = SolidShape::Quad4;
  int edgeNodes = 0;  // 2 (LINE2) or 3 (LINE3) for an edge, 0 for a face
};

bool faceShape(size_t nodes, const std::string& sideTopology, SolidShape& shape) {
  if (sideTopology == "QUAD4" && nodes == 4) shape = SolidShape::Quad4;
  else if (sideTopology == "QUAD8" && nodes == 8) shape = SolidShape::Quad8;
  else if (sideTopology == "TRI3" && nodes == 3) shape = SolidShape::Tri3;
  else if (sideTopology == "TRI6" && nodes == 6) shape = SolidShape::Tri6;
  else return false;
  return true;
}

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

// Position, tangents and shape functions of a face at (xi, eta).
struct FacePoint {
  Point3 x{}, dxi{}, deta{};
  std::vector<double> N;
};

// An edge at xi in [-1, 1]: LINE2 linear; LINE3 quadratic with its mid node third (Exodus).
FacePoint evaluateEdge(const Face& f, double xi) {
  FacePoint p;
  std::vector<double> dN;
  if (f.edgeNodes == 2) {
    p.N = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    dN = {-0.5, 0.5};
  } else {
    p.N = {0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi};
    dN = {xi - 0.5, xi + 0.5, -2 * xi};
  }
  for (size_t a = 0; a < f.x.size(); ++a)
    for (int d = 0; d < 3; ++d) {
      p.x[d] += p.N[a] * f.x[a][d];
      p.dxi[d] += dN[a] * f.x[a][d];
    }
  p.deta = {0.0, 0.0, 1.0};
  return p;
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

bool isTriangle(const Face& f) {
  return !f.edgeNodes && (f.shape == SolidShape::Tri3 || f.shape == SolidShape::Tri6);
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

// Closest point of x on the face from the face's centre.
bool projectOnFace(const Face& f, const Point3& x, double& xi, double& eta) {
  if (!f.edgeNodes && f.shape == SolidShape::Quad4)
    return projectOnQuad({f.x[0], f.x[1], f.x[2], f.x[3]}, x, xi, eta);
  xi = eta = isTriangle(f) ? 1.0 / 3.0 : 0.0;
  return gaussNewtonProjection([&](double s, double t) { return evaluateFace(f, s, t); }, x, xi, eta);
}

bool insideFace(const Face& f, double xi, double eta) {
  const double tol = 1e-8;
  if (f.edgeNodes) return std::abs(xi) <= 1.0 + tol;
  if (isTriangle(f)) return xi >= -tol && eta >= -tol && xi + eta <= 1.0 + tol;
  return std::abs(xi) <= 1.0 + tol && std::abs(eta) <= 1.0 + tol;
}

// Each slave node's share of the slave surface's area.
// (axisymmetric: the edges are rings, their length element weighted by 2 pi r).
std::map<int, double> tributaryAreas(const std::vector<Face>& slave, bool axisymmetric) {
  std::map<int, double> area;
  const double g = 1.0 / std::sqrt(3.0);
  for (const Face& f : slave) {
    if (!f.edgeNodes && f.shape == SolidShape::Quad4) {  // 2 x 2 Gauss, as it always was
      for (double xi : {-g, g})
        for (double eta : {-g, g}) {
          const QuadPoint q = evaluateQuad({f.x[0], f.x[1], f.x[2], f.x[3]}, xi, eta);
          const Point3 n = cross(q.dxi, q.deta);
          const double J = std::sqrt(dot(n, n));
          for (int i = 0; i < 4; ++i) area[f.nodes[i]] += q.N[i] * J;
        }
      continue;
    }
    const int n = static_cast<int>(f.nodes.size());
    DenseMatrix m(n, n);
    QuadratureRule line;  // 3-point Gauss on [-1, 1] for edges
    line.points = {{-std::sqrt(0.6), 0, 0}, {0, 0, 0}, {std::sqrt(0.6), 0, 0}};
    line.weights = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const QuadratureRule& rule = f.edgeNodes ? line : massRule(f.shape);
    for (int k = 0; k < rule.size(); ++k) {
      const FacePoint q = evaluateFace(f, rule.points[k][0], rule.points[k][1]);
      const double ring = axisymmetric && f.edgeNodes ? 2.0 * M_PI * q.x[0] : 1.0;
      const double J = norm(cross(q.dxi, q.deta)) * rule.weights[k] * ring;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) m(a, b) += q.N[a] * q.N[b] * J;
    }
    const bool quadratic = f.edgeNodes ? f.edgeNodes == 3 : f.shape == SolidShape::Tri6 || f.shape == SolidShape::Quad8;
    const std::vector<double> lumped = quadratic ? hrzLumping(m) : rowSumLumping(m);
    for (int a = 0; a < n; ++a) area[f.nodes[a]] += lumped[a];
  }
  return area;
}

}  // namespace

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

PairingResult pairNodeToFace(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  const std::vector<Face> master = facesOf(mesh, def.masterSideSet);
  const std::map<int, double> area = tributaryAreas(facesOf(mesh, def.slaveSideSet), def.axisymmetric);
  PairingResult res;
  for (const auto& [node, a] : area) {
    const Point3& xs = mesh.coords[node];
    SlaveProjection best;
    double bestDist = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < master.size(); ++k) {
      double xi, eta;
      if (!projectOnFace(master[k], xs, xi, eta) || !insideFace(master[k], xi, eta)) continue;
      const FacePoint q = evaluateFace(master[k], xi, eta);
      const Point3 d = (xs - q.x);
      const double dist = std::sqrt(dot(d, d));
      if (!(dist < bestDist - 1e-15)) continue;
      Point3 n = cross(q.dxi, q.deta);
      const double len = std::sqrt(dot(n, n));
      for (double& v : n) v /= len;
      const double g0 = dot(d, n);
      if (std::abs(g0) > def.searchDistance) continue;
      bestDist = dist;
      best.pair = pairIndex;
      best.slaveNode = node;
      best.masterFace = static_cast<int>(k);
      best.masterNodes = master[k].nodes;
      best.weights = q.N;
      best.xi = xi;
      best.eta = eta;
      best.normal = n;
      best.gap0 = g0;
      best.area = a;
    }
    if (best.slaveNode < 0) res.unpaired.push_back(node);
    else res.projections.push_back(best);
  }
  if (res.projections.empty())
    throw std::invalid_argument("no node of slave side set '" + def.slaveSideSet +
                                "' projects onto a face of master side set '" + def.masterSideSet +
                                "' within the search distance " + std::to_string(def.searchDistance) + " m");
  return res;
}

PairingResult pairNodeToObstacle(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  PairingResult res;
  std::map<int, double> slaves;
  if (!def.slaveNodeSet.empty()) {
    if (const NodeSet* ns = mesh.findNodeSet(def.slaveNodeSet))
      for (int n : ns->nodes) slaves[n] = 0.0;  // nodes of beams or point masses: no area
  } else {
    slaves = tributaryAreas(facesOf(mesh, def.slaveSideSet), def.axisymmetric);
  }
  for (const auto& [node, a] : slaves) {
    const ObstacleDistance d = distanceTo(def.obstacle, mesh.coords[node], 0.0);
    SlaveProjection sp;
    sp.pair = pairIndex;
    sp.slaveNode = node;
    sp.normal = d.normal;
    sp.gap0 = d.gap;
    sp.area = a;
    res.projections.push_back(sp);
  }
  return res;
}

PairingResult pairNodeToNode(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  const NodeSet* slaves = mesh.findNodeSet(def.slaveNodeSet);
  const NodeSet* masters = mesh.findNodeSet(def.masterNodeSet);
  if (!slaves || !masters) throw std::invalid_argument("node set not found");
  if (slaves->nodes.size() != masters->nodes.size())
    throw std::invalid_argument("slave node set '" + def.slaveNodeSet + "' has " +
                                std::to_string(slaves->nodes.size()) + " nodes, master node set '" +
                                def.masterNodeSet + "' " + std::to_string(masters->nodes.size()));
  PairingResult res;
  std::vector<char> used(masters->nodes.size(), 0);
  std::vector<int> sorted = slaves->nodes;
  std::sort(sorted.begin(), sorted.end());
  for (int s : sorted) {
    size_t best = 0;
    double bestD = INFINITY;
    for (size_t j = 0; j < masters->nodes.size(); ++j) {
      const Vec3 d = mesh.coords[s] - mesh.coords[masters->nodes[j]];
      if (dot(d, d) < bestD) bestD = dot(d, d), best = j;
    }
    if (used[best])
      throw std::invalid_argument("master node " + std::to_string(masters->nodes[best] + 1) +
                                  " is the nearest of two slave nodes");
    used[best] = 1;
    SlaveProjection sp;
    sp.pair = pairIndex;
    sp.slaveNode = s;
    sp.masterNodes = {masters->nodes[best]};
    sp.weights = {1.0};
    sp.normal = def.nodeNormal;
    sp.gap0 = dot(def.nodeNormal, mesh.coords[s] - mesh.coords[masters->nodes[best]]) - def.nodeOffset;
    res.projections.push_back(sp);
  }
  return res;
}

}  // namespace choc
