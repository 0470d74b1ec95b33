// ContactManager::checkPenetration: slave nodes through a rigid obstacle, measured against the
// size of the slave faces around them (ContactManager.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include "contact/ContactFaces.hpp"
#include "contact/ContactManager.hpp"
#include "core/Format.hpp"

namespace choc {

std::vector<double> slaveFaceSizes(const Mesh& mesh, const std::vector<PairDefinition>& pairs_,
                                   const std::vector<ContactConstraint>& constraints_) {
  std::map<std::pair<int, int>, double> shortest;  // (pair, slave node) -> shortest edge of its faces
  for (size_t p = 0; p < pairs_.size(); ++p) {
    // A slave node set (no faces: a shock link's node against an obstacle) has no size to judge by.
    if (!pairs_[p].hasObstacle || pairs_[p].slaveSideSet.empty()) continue;
    std::vector<Face> faces;
    try {
      faces = facesOf(mesh, pairs_[p].slaveSideSet);
    } catch (const std::invalid_argument&) {
      continue;  // the pairing has accepted the set: only its faces' sizes are not known
    }
    for (const Face& f : faces) {
      const int corners = f.edgeNodes > 0 ? 2 : isTriangle(f) ? 3 : 4;
      double edge = std::numeric_limits<double>::infinity();
      for (int a = 0; a < corners; ++a) {
        const Point3 d = f.x[size_t(a)] - f.x[size_t((a + 1) % corners)];
        edge = std::min(edge, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      }
      for (int n : f.nodes) {
        auto [it, fresh] = shortest.emplace(std::make_pair(int(p), n), edge);
        if (!fresh) it->second = std::min(it->second, edge);
      }
    }
  }
  std::vector<double> size(constraints_.size(), 0.0);
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const SlaveProjection& g = constraints_[s].geometry;
    const auto it = shortest.find({g.pair, g.slaveNode});
    if (g.masterFace < 0 && it != shortest.end()) size[s] = it->second;
  }
  return size;
}

void ContactManager::checkPenetration(const Vector& u, ElementValidity& v) const {
  if (!hasObstacles_ || !v.failure.empty()) return;
  const std::vector<double> g = gaps(u);
  double worst = 0.0;
  size_t at = 0;
  for (size_t s = 0; s < g.size() && s < slaveSize_.size(); ++s) {
    if (!(slaveSize_[s] > 0)) continue;
    const double ratio = -g[s] / slaveSize_[s];
    if (ratio > worst) worst = ratio, at = s;
  }
  if (!(worst > kPenetrationWarning)) return;
  const SlaveProjection& sp = constraints_[at].geometry;
  const bool failed = worst > kPenetrationLimit;
  const std::string line =
      format("node %d of pair '%s' is %.3g m through the rigid obstacle, %.3g of its faces' size (%s %g): ",
             sp.slaveNode + 1, pairs_[size_t(sp.pair)].name.c_str(), -g[at], worst, failed ? "limit" : "bound",
             failed ? kPenetrationLimit : kPenetrationWarning) +
      (method().hasMultipliers() ? "the contact no longer holds the surface (a smaller step or a finer mesh?)"
                                 : "raise 'Penalty Stiffness', or use Lagrange contact");
  if (failed)
    v.failure = line;
  else if (v.warning.empty())
    v.warning = line;
}

}  // namespace choc
