#include "contact/ContactPairing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace choc {

namespace {


struct Face {
  std::array<int, 4> nodes;
  std::array<Point3, 4> x;
};

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
    const auto nodes = mesh.sideNodes(ss->elements[k], ss->sides[k]);
    if (nodes.size() != 4)
      throw std::invalid_argument("side set '" + name + "' is not made of QUAD4 faces");
    Face f;
    for (int i = 0; i < 4; ++i) {
      f.nodes[i] = nodes[i];
      f.x[i] = mesh.coords[nodes[i]];
    }
    faces.push_back(f);
  }
  if (faces.empty()) throw std::invalid_argument("side set '" + name + "' is empty");
  return faces;
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
  for (int it = 0; it < 30; ++it) {
    const QuadPoint q = evaluateQuad(c, xi, eta);
    const Point3 d = (q.x - x);
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

PairingResult pairNodeToFace(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  const std::vector<Face> master = facesOf(mesh, def.masterSideSet);
  const std::vector<Face> slave = facesOf(mesh, def.slaveSideSet);
  // Tributary areas: integral of each slave node's shape function (2 x 2 Gauss).
  std::map<int, double> area;
  const double g = 1.0 / std::sqrt(3.0);
  for (const Face& f : slave)
    for (double xi : {-g, g})
      for (double eta : {-g, g}) {
        const QuadPoint q = evaluateQuad(f.x, xi, eta);
        const Point3 n = cross(q.dxi, q.deta);
        const double J = std::sqrt(dot(n, n));
        for (int i = 0; i < 4; ++i) area[f.nodes[i]] += q.N[i] * J;
      }
  PairingResult res;
  const double inside = 1.0 + 1e-8;
  for (const auto& [node, a] : area) {
    const Point3& xs = mesh.coords[node];
    SlaveProjection best;
    double bestDist = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < master.size(); ++k) {
      double xi, eta;
      if (!projectOnQuad(master[k].x, xs, xi, eta)) continue;
      if (std::abs(xi) > inside || std::abs(eta) > inside) continue;
      const QuadPoint q = evaluateQuad(master[k].x, xi, eta);
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

}  // namespace choc
