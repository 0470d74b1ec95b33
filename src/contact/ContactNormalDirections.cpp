// The directions a contact constrains at each contact node (contact/ContactNormalDirections.hpp).
#include "contact/ContactNormalDirections.hpp"

#include <algorithm>
#include <cmath>

#include "contact/ContactFaces.hpp"
#include "contact/ContactManager.hpp"
#include "contact/RigidObstacle.hpp"
#include "materials/SymmetricEigen.hpp"

namespace choc {

using Sym3 = Mat3;

namespace {

void addOuter(Sym3& S, const Point3& n, double w) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) S[i][j] += w * n[i] * n[j];
}

// A pair's share: per node, the area-weighted mean of n n^T over its faces in the pair's side
// sets, or n n^T of its node set's normal.
void addPair(const PairDefinition& pair, const Mesh& mesh, std::vector<Sym3>& S) {
  std::vector<Sym3> share(mesh.coords.size(), Sym3{});
  std::vector<double> weight(mesh.coords.size(), 0.0);
  for (const std::string& name : {pair.slaveSideSet, pair.masterSideSet}) {
    if (name.empty()) continue;
    for (const Face& f : facesOf(mesh, name)) {
      const double c = isTriangle(f) ? 1.0 / 3.0 : 0.0;
      const FacePoint p = evaluateFace(f, c, c);
      const Point3 a = cross(p.dxi, p.deta);
      const double area = norm(a);
      if (!(area > 0)) continue;
      const Point3 n{a[0] / area, a[1] / area, a[2] / area};
      for (int node : f.nodes) {
        addOuter(share[size_t(node)], n, area);
        weight[size_t(node)] += area;
      }
    }
  }
  for (const std::string& name : {pair.slaveNodeSet, pair.masterNodeSet}) {
    const NodeSet* ns = name.empty() ? nullptr : mesh.findNodeSet(name);
    for (int node : ns ? ns->nodes : std::vector<int>{}) {
      const Point3 n = pair.hasObstacle ? distanceTo(pair.obstacle, mesh.coords[size_t(node)], 0.0).normal
                                        : pair.nodeNormal;
      if (!(norm(n) > 0)) continue;
      addOuter(share[size_t(node)], n, 1.0 / dot(n, n));
      weight[size_t(node)] += 1.0;
    }
  }
  for (size_t k = 0; k < S.size(); ++k)
    if (weight[k] > 0)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) S[k][i][j] += share[k][i][j] / weight[k];
}

// The node's constrained directions within its unknowns: S restricted to the free components.
std::vector<Point3> directionsOf(Sym3 S, std::uint8_t free) {
  for (int i = 0; i < 3; ++i)
    if (!((free >> i) & 1u))
      for (int j = 0; j < 3; ++j) S[i][j] = S[j][i] = 0.0;
  const SymmetricEigen e = symmetricEigen(S);
  const double largest = std::max({e.values[0], e.values[1], e.values[2]});
  std::vector<Point3> out;
  if (!(largest > 0)) return out;
  std::array<int, 3> order{0, 1, 2};  // the largest first
  std::sort(order.begin(), order.end(), [&](int a, int b) { return e.values[a] > e.values[b]; });
  for (int A : order)
    if (e.values[A] >= 0.25 * largest) out.push_back({e.vectors[0][A], e.vectors[1][A], e.vectors[2][A]});
  return out;
}

}  // namespace

std::vector<std::vector<Point3>> contactNormalDirections(const ContactManager& contact, const Mesh& mesh,
                                                         const DofMap& dofs) {
  std::vector<Sym3> S(mesh.coords.size(), Sym3{});
  for (int p = 0; p < contact.numPairs(); ++p) addPair(contact.pair(p), mesh, S);
  std::vector<std::vector<Point3>> out(mesh.coords.size());
  for (size_t k = 0; k < S.size(); ++k) out[k] = directionsOf(S[k], dofs.freeMask(int(k)));
  return out;
}

}  // namespace choc
