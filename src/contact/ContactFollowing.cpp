// ContactManager: the pairs whose search follows the motion ('Search' = current).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "contact/ContactManager.hpp"

namespace choc {

namespace {

// A followed constraint keeps its coefficients while none moves by more than this (they are
// of order 1: the normal, and the normal times a shape-function weight; measured as vectors,
// coefficientChange). The linearised gap is exact at
// the start of every step whatever the coefficients, so a kept set errs by at most this
// fraction of the step's displacement increment, and the effective matrix is not refactored
// for the 1e-9 tilts of a face loaded unevenly.
constexpr double kCoefficientTolerance = 1e-6;

bool sameDofs(const std::vector<std::pair<GO, double>>& a, const std::vector<std::pair<GO, double>>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k)
    if (a[k].first != b[k].first) return false;
  return true;
}

// How far the constraint's coefficients moved from projection a to b, the same in any frame:
// the slave node's coefficient vector is the normal n, a master node's -w_i n, and the largest
// Euclidean change of these vectors is measured (a largest change of one component would depend
// on the frame the scene is drawn in: SDNL111's bars turned as a whole moved by 6e-7 of their
// peak). +inf when the master nodes differ.
double coefficientChange(const SlaveProjection& a, const SlaveProjection& b) {
  if (a.masterNodes != b.masterNodes || a.weights.size() != b.weights.size() ||
      a.gapGradient.size() != b.gapGradient.size())
    return std::numeric_limits<double>::infinity();
  const auto distance = [](const Point3& p, const Point3& q) {
    const Point3 d{p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    return std::sqrt(dot(d, d));
  };
  double m = distance(a.normal, b.normal);
  for (size_t i = 0; i < a.gapGradient.size(); ++i) {  // a mortar row: each node's coefficients
    if (a.gapGradient[i].first != b.gapGradient[i].first) return std::numeric_limits<double>::infinity();
    m = std::max(m, distance(a.gapGradient[i].second, b.gapGradient[i].second));
  }
  for (size_t i = 0; i < a.weights.size(); ++i) {
    const Point3 wa{a.weights[i] * a.normal[0], a.weights[i] * a.normal[1], a.weights[i] * a.normal[2]};
    const Point3 wb{b.weights[i] * b.normal[0], b.weights[i] * b.normal[1], b.weights[i] * b.normal[2]};
    m = std::max(m, distance(wa, wb));
  }
  return m;
}

// The tangential part of the slave node's offset from its master point, at the followed positions.
Vec3 tangentialOffset(const FollowedSurfaces& followed, const ContactConstraint& c) {
  const SlaveProjection& g = c.geometry;
  if (g.masterNodes.empty()) return Vec3{0, 0, 0};
  Vec3 d = followed.position(g.slaveNode);
  for (size_t i = 0; i < g.masterNodes.size(); ++i) {
    const Point3 xm = followed.position(g.masterNodes[i]);
    for (int k = 0; k < 3; ++k) d[k] -= g.weights[i] * xm[k];
  }
  const double dn = dot(d, g.normal);
  for (int k = 0; k < 3; ++k) d[k] -= dn * g.normal[k];
  return d;
}

// The mortar pairs' projections on the current configuration, by pair and slave node.
std::map<int, std::map<int, SlaveProjection>> followMortar(const FollowedSurfaces& followed,
                                                           const std::vector<PairDefinition>& pairs) {
  std::map<int, std::map<int, SlaveProjection>> out;
  for (size_t p = 0; p < pairs.size(); ++p) {
    if (!followed.follows(int(p)) || !followed.mortar(int(p))) continue;
    const PairingResult r =
        mortarPairing(followed.slaveFaces(int(p)), followed.masterSearch(int(p)), pairs[p], int(p));
    for (const SlaveProjection& sp : r.projections)
      if (!sp.masterNodes.empty()) out[int(p)][sp.slaveNode] = sp;
  }
  return out;
}

}  // namespace

void ContactManager::followSurfaces(const Vector& u) {
  followed_->place(gatherReplicated(*map_, followed_->dofs(), u), true);
  const auto mortar = followMortar(*followed_, pairs_);
  bool topology = false, turned = false;
  for (size_t s = 0; s < constraints_.size(); ++s) {
    ContactConstraint& c = constraints_[s];
    const int p = c.geometry.pair;
    if (!followed_->follows(p)) continue;
    SlaveProjection sp = c.geometry;
    SurfaceHit hit;
    double gap = pairs_[p].searchDistance;
    const bool isMortar = followed_->mortar(p);
    const SlaveProjection* overlap = nullptr;
    if (const auto it = mortar.find(p); it != mortar.end())
      if (const auto jt = it->second.find(sp.slaveNode); jt != it->second.end()) overlap = &jt->second;
    if (overlap) {
      sp = *overlap;
      gap = sp.gap0;
    } else if (!isMortar && followed_->find(p, followed_->position(sp.slaveNode), hit, sp.masterFace)) {
      sp.masterFace = hit.face;
      sp.masterNodes = followed_->face(p, hit.face).nodes;
      sp.weights = hit.N;
      sp.xi = hit.xi;
      sp.eta = hit.eta;
      sp.normal = hit.normal;
      gap = hit.gap;
    } else {
      sp.masterFace = -1;
      sp.masterNodes.clear();
      sp.weights.clear();
      sp.normal = Point3{0, 0, 0};
      if (set_.status[s]) {  // it left its master surface: no force, no multiplier
        set_.status[s] = 0;
        set_.lambda[s] = 0.0;
        ++set_.version;
      }
    }
    ContactConstraint next = makeContactConstraint(c.reference, *dofs_, sp, true);
    if (!sameDofs(next.terms, c.terms)) {
      topology = true;
      c.terms = next.terms;
      c.componentTerm = next.componentTerm;
      c.geometry = sp;
    } else if (coefficientChange(sp, c.geometry) > kCoefficientTolerance) {
      turned = true;
      c.terms = next.terms;
      c.geometry = sp;
    }  // else the coefficients stay: the linearisation point moves, not the matrix
    double bu = 0.0;
    for (const auto& [dof, coeff] : c.terms) bu += coeff * followed_->displacement(dof);
    c.geometry.gap0 = gap - bu;
    slipStart_[s] = tangentialOffset(*followed_, c);
  }
  paired_ = true;
  if (topology) ++topologyVersion_;
  if (topology || turned) {
    indexTerms();
    ++geometryVersion_;
  }
}

void ContactManager::commitMotion(const Vector& u) {
  if (friction_)
    friction_->commitMotion([&] { return contactValues(u); }, [&](const std::vector<double>& x) { return gapsAt(x); });
  if (!followed_ || !paired_) return;
  followed_->place(gatherReplicated(*map_, followed_->dofs(), u), false);
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const ContactConstraint& c = constraints_[s];
    if (!set_.status[s] || !followed_->follows(c.geometry.pair)) continue;
    const Vec3 d = tangentialOffset(*followed_, c);
    slip_[s] += norm(Vec3{d[0] - slipStart_[s][0], d[1] - slipStart_[s][1], d[2] - slipStart_[s][2]});
  }
}

}  // namespace choc

namespace choc {

// The pairing of the followed constraints in a checkpoint: a constraint keeps its coefficients
// while they move by less than kCoefficientTolerance, so the pairing in use depends on the
// steps before; a restarted run takes it from the checkpoint, not from a fresh search.
// Per constraint: master face (-1: none), xi, eta, the normal, the number of weights and them;
// for a mortar pair then its master nodes, its area, and its row (gapGradient: the number of
// nodes, then node and derivative by each).
void ContactManager::archivePairing(StateArchive& a) const {
  std::vector<double> g;
  for (const ContactConstraint& c : constraints_) {
    if (!followed_->follows(c.geometry.pair)) continue;
    const SlaveProjection& sp = c.geometry;
    g.insert(g.end(), {double(sp.masterFace), sp.xi, sp.eta, sp.normal[0], sp.normal[1], sp.normal[2],
                       double(sp.weights.size())});
    g.insert(g.end(), sp.weights.begin(), sp.weights.end());
    if (followed_->mortar(sp.pair)) {  // the master nodes span several faces; the area moves
      for (int n : sp.masterNodes) g.push_back(double(n));
      g.push_back(sp.area);
      g.push_back(double(sp.gapGradient.size()));
      for (const auto& [node, d] : sp.gapGradient) g.insert(g.end(), {double(node), d[0], d[1], d[2]});
    }
  }
  a.putVector("contact/pairing", g);
}

void ContactManager::restorePairing(const StateArchive& a) {
  const std::vector<double> g = a.getVector<double>("contact/pairing");
  size_t k = 0;
  for (ContactConstraint& c : constraints_) {
    if (!followed_->follows(c.geometry.pair)) continue;
    if (k + 7 > g.size()) throw StateRecordError("record 'contact/pairing' is shorter than the followed constraints");
    SlaveProjection sp = c.geometry;
    sp.masterFace = int(g[k]);
    sp.xi = g[k + 1];
    sp.eta = g[k + 2];
    sp.normal = Point3{g[k + 3], g[k + 4], g[k + 5]};
    const size_t nw = size_t(g[k + 6]);
    k += 7;
    if (k + nw > g.size()) throw StateRecordError("record 'contact/pairing' is shorter than the followed constraints");
    sp.weights.assign(g.begin() + long(k), g.begin() + long(k + nw));
    k += nw;
    sp.masterNodes = sp.masterFace >= 0 ? followed_->face(sp.pair, sp.masterFace).nodes : std::vector<int>();
    if (followed_->mortar(sp.pair)) {
      if (k + nw + 1 > g.size()) throw StateRecordError("record 'contact/pairing' is shorter than the followed constraints");
      sp.masterNodes.assign(nw, 0);
      for (size_t i = 0; i < nw; ++i) sp.masterNodes[i] = int(g[k + i]);
      sp.area = g[k + nw];
      k += nw + 1;
      if (k >= g.size() || k + 1 + 4 * size_t(g[k]) > g.size())
        throw StateRecordError("record 'contact/pairing' is shorter than the followed constraints");
      const size_t ng = size_t(g[k]);
      sp.gapGradient.resize(ng);
      for (size_t i = 0; i < ng; ++i)
        sp.gapGradient[i] = {int(g[k + 1 + 4 * i]), Point3{g[k + 2 + 4 * i], g[k + 3 + 4 * i], g[k + 4 + 4 * i]}};
      k += 1 + 4 * ng;
    }
    const ContactConstraint next = makeContactConstraint(c.reference, *dofs_, sp, true);
    c.geometry = sp;
    c.terms = next.terms;
    c.componentTerm = next.componentTerm;
  }
  indexTerms();
  ++topologyVersion_;
  ++geometryVersion_;
}

}  // namespace choc
