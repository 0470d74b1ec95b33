// Mortar pairing with dual Lagrange multipliers (ContactPairing.hpp, pairMortar).
#include <algorithm>
#include <cmath>
#include <map>

#include "contact/ContactPairing.hpp"
#include "contact/MortarLinearization.hpp"
#include "contact/MortarSegments.hpp"
#include "contact/SurfaceSearch.hpp"
#include "fem/Quadrature.hpp"

namespace choc {

namespace {

struct Box {
  Point3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
};

Box boxOf(const Face& f, double widen) {
  Box b;
  for (const Point3& x : f.x)
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = std::min(b.lo[d], x[d] - widen);
      b.hi[d] = std::max(b.hi[d], x[d] + widen);
    }
  return b;
}

bool overlap(const Box& a, const Box& b) {
  for (int d = 0; d < 3; ++d)
    if (a.hi[d] < b.lo[d] || b.hi[d] < a.lo[d]) return false;
  return true;
}

// int N_a over the face (rings: 2 pi r).
std::vector<double> shapeIntegrals(const Face& f, bool axisymmetric) {
  const QuadratureRule& rule = f.edgeNodes ? gaussBoxRule(1, 3) : massRule(f.shape);
  std::vector<double> I(f.nodes.size(), 0.0);
  for (int k = 0; k < rule.size(); ++k) {
    const FacePoint q = evaluateFace(f, rule.points[k][0], rule.points[k][1]);
    const double J = norm(cross(q.dxi, q.deta)) * rule.weights[k] * (axisymmetric ? 2.0 * M_PI * q.x[0] : 1.0);
    for (size_t a = 0; a < I.size(); ++a) I[a] += q.N[a] * J;
  }
  return I;
}

// What one slave node gathers over the segments its dual function covers.
struct NodeSums {
  double D = 0, G = 0, full = 0;  // int Phi_j, int Phi_j gap, int N_j over its faces
  std::map<int, double> M;         // master node -> int Phi_j N_m
  int firstFace = -1;
  Point3 normal{0, 0, 0};          // sum of its faces' outward normals there
  Point3 nu{};                     // the contact normal: that sum normalised, turned to the slave
  // The derivatives (MortarLinearization.hpp): of D, of G with nu held, of G through nu; and
  // int Phi_j (x_s - x_m).
  NodeGradient dD, dG, dNu;
  Point3 Gv{0, 0, 0};
};

void addTo(NodeGradient& to, const NodeGradient& from) {
  for (const auto& [node, g] : from)
    for (int c = 0; c < 3; ++c) to[node][c] += g[c];
}

// The derivatives of slave face f's overlap with master face m added to its nodes' sums.
void addOverlapDerivatives(const Face& f, const Face& m, bool axisymmetric, std::map<int, NodeSums>& sums) {
  std::vector<Point3> nu;
  for (int n : f.nodes) nu.push_back(sums[n].nu);
  const OverlapDerivatives d = overlapDerivatives(f, m, nu, axisymmetric);
  for (size_t a = 0; a < d.dD.size(); ++a) {
    NodeSums& s = sums[f.nodes[a]];
    addTo(s.dD, d.dD[a]);
    addTo(s.dG, d.dG[a]);
    for (int c = 0; c < 3; ++c) s.Gv[c] += d.Gv[a][c];
  }
}

// dnu_j . Gv_j = w_j . dS_j over the faces of every slave node (MortarLinearization.hpp).
void addNormalDerivatives(const std::vector<Face>& slave, std::map<int, NodeSums>& sums) {
  for (const Face& f : slave)
    for (size_t a = 0; a < f.nodes.size(); ++a) {
      NodeSums& s = sums[f.nodes[a]];
      const double l = norm(s.normal);
      const Point3 u{s.normal[0] / l, s.normal[1] / l, s.normal[2] / l};
      const double along = dot(u, s.Gv);
      const Point3 w{-(s.Gv[0] - along * u[0]) / l, -(s.Gv[1] - along * u[1]) / l, -(s.Gv[2] - along * u[2]) / l};
      addNormalDerivative(f, int(a), w, s.dNu);
    }
}

// dg_j = (dG_j + dNu_j) / D_j - g_j dD_j / D_j per node; a node whose derivative is below
// 1e-13 (the coefficients are of order 1: round-off of terms that cancel) is left out.
std::vector<std::pair<int, Point3>> gapGradient(const NodeSums& s) {
  NodeGradient sum = s.dG;
  addTo(sum, s.dNu);
  for (const auto& [node, g] : s.dD) sum[node];
  std::vector<std::pair<int, Point3>> out;
  const double gap = s.G / s.D;
  for (const auto& [node, g] : sum) {
    Point3 d = g;
    const auto it = s.dD.find(node);
    for (int c = 0; c < 3; ++c) d[c] = d[c] / s.D - (it == s.dD.end() ? 0.0 : gap * it->second[c] / s.D);
    if (norm(d) > 1e-13) out.push_back({node, d});
  }
  return out;
}

// Per slave node: int N_j over its faces and the contact normal from its faces' normals.
std::map<int, NodeSums> slaveNodeNormals(const std::vector<Face>& slave, bool axisymmetric) {
  std::map<int, NodeSums> sums;
  for (const Face& f : slave) {
    const std::vector<double> I = shapeIntegrals(f, axisymmetric);
    for (size_t a = 0; a < f.nodes.size(); ++a) {
      NodeSums& s = sums[f.nodes[a]];
      s.full += I[a];
      const Point3 n = nodeNormal(f, int(a));
      for (int d = 0; d < 3; ++d) s.normal[d] += n[d];
    }
  }
  for (auto& [node, s] : sums) {
    const double l = norm(s.normal);
    s.nu = {-s.normal[0] / l, -s.normal[1] / l, -s.normal[2] / l};
  }
  return sums;
}

// The integrals of slave face f's dual functions over its overlaps with the master faces
// near it, added to its nodes' sums.
void integrateOverlaps(const Face& f, const SurfaceSearch& search, const PairDefinition& def,
                       std::map<int, NodeSums>& sums) {
  const std::vector<Face>& master = search.faces();
  const DenseMatrix A = dualBasis(f, def.axisymmetric);
  const Box box = boxOf(f, def.searchDistance);
  for (const int mf : search.candidates(box.lo, box.hi)) {  // master faces near the slave face
    if (!overlap(box, boxOf(master[mf], 0.0))) continue;
    const std::vector<MortarPoint> pts = mortarPoints(f, master[mf], def.axisymmetric);
    if (pts.empty()) continue;
    if (!(std::abs(dot(pts[0].xs - pts[0].xm, sums[f.nodes[0]].nu)) <= def.searchDistance)) continue;
    for (const MortarPoint& p : pts) {
      const std::vector<double> phi = dualShapes(A, p.Ns);
      for (size_t a = 0; a < f.nodes.size(); ++a) {
        NodeSums& s = sums[f.nodes[a]];
        const double w = phi[a] * p.weight;
        s.D += w;
        s.G += w * dot(s.nu, p.xs - p.xm);
        for (size_t b = 0; b < p.Nm.size(); ++b) s.M[master[mf].nodes[b]] += w * p.Nm[b];
        if (s.firstFace < 0) s.firstFace = int(mf);
      }
    }
    addOverlapDerivatives(f, master[mf], def.axisymmetric, sums);
  }
}

// One projection per slave node, in ascending node number: its gap, area and master weights
// (the averages of its dual function), or unpaired when it overhangs the master.
PairingResult projectionsOf(const std::map<int, NodeSums>& sums, const PairDefinition& def, int pairIndex) {
  PairingResult res;
  for (const auto& [node, s] : sums) {
    SlaveProjection sp;
    sp.pair = pairIndex;
    sp.slaveNode = node;
    if (!(s.D >= 0.25 * s.full)) {  // overhanging the master: no constraint
      res.unpaired.push_back(node);
      if (def.followMotion) {  // kept, without master nodes, until an overlap covers it
        sp.masterFace = -1;
        sp.gap0 = def.searchDistance;
        sp.area = s.full;
        res.projections.push_back(sp);
      }
      continue;
    }
    sp.masterFace = s.firstFace;
    sp.normal = s.nu;
    sp.gap0 = s.G / s.D;
    sp.area = s.D;
    sp.gapGradient = gapGradient(s);
    for (const auto& [m, v] : s.M)
      if (std::abs(v) > 1e-14 * s.D) sp.masterNodes.push_back(m), sp.weights.push_back(v / s.D);
    res.projections.push_back(sp);
  }
  return res;
}

}  // namespace

PairingResult pairMortar(const Mesh& mesh, const PairDefinition& def, int pairIndex) {
  const std::vector<Face> slave = facesOf(mesh, def.slaveSideSet);  // dualBasis rejects quadratic faces
  PairingResult res = mortarPairing(slave, SurfaceSearch(facesOf(mesh, def.masterSideSet), def.searchDistance), def, pairIndex);
  if (res.projections.size() == (def.followMotion ? res.unpaired.size() : 0))
    throw std::invalid_argument("no face of slave side set '" + def.slaveSideSet + "' overlaps a face of master side set '" +
                                def.masterSideSet + "' within the search distance " +
                                std::to_string(def.searchDistance) + " m");
  return res;
}

PairingResult mortarPairing(const std::vector<Face>& slave, const SurfaceSearch& search,
                            const PairDefinition& def, int pairIndex) {
  std::map<int, NodeSums> sums = slaveNodeNormals(slave, def.axisymmetric);
  for (const Face& f : slave) integrateOverlaps(f, search, def, sums);
  addNormalDerivatives(slave, sums);
  return projectionsOf(sums, def, pairIndex);
}

}  // namespace choc
