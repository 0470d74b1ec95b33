#include "contact/ContactPairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "contact/ContactFaces.hpp"
#include "contact/SurfaceSearch.hpp"
#include "fem/DenseMatrix.hpp"
#include "fem/MassLumping.hpp"
#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

namespace choc {

namespace {

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
    const QuadratureRule& rule = f.edgeNodes ? gaussBoxRule(1, 3) : massRule(f.shape);  // edges: 3-point Gauss
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

PairingResult pairNodeToFace(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  const SurfaceSearch master(facesOf(mesh, def.masterSideSet), def.searchDistance);
  const std::map<int, double> area = tributaryAreas(facesOf(mesh, def.slaveSideSet), def.axisymmetric);
  PairingResult res;
  for (const auto& [node, a] : area) {  // ascending node number
    SurfaceHit hit;
    SlaveProjection best;
    best.pair = pairIndex;
    best.slaveNode = node;
    best.area = a;
    if (!master.closest(mesh.coords[node], hit)) {
      res.unpaired.push_back(node);
      if (def.followMotion) {  // kept, without a master face, until a search finds one
        best.masterFace = -1;
        best.gap0 = def.searchDistance;
        res.projections.push_back(best);
      }
      continue;
    }
    best.masterFace = hit.face;
    best.masterNodes = master.faces()[hit.face].nodes;
    best.weights = hit.N;
    best.xi = hit.xi;
    best.eta = hit.eta;
    best.normal = hit.normal;
    best.gap0 = hit.gap;
    res.projections.push_back(best);
  }
  if (res.projections.size() == (def.followMotion ? res.unpaired.size() : 0))
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
