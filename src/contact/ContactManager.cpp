#include "contact/ContactManager.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {

// The terms of every constraint's relative motion u_s - sum_i w_i u_i, per component.
SlipTerms slipTermsOf(const std::vector<ContactConstraint>& constraints, const DofMap& dofs) {
  SlipTerms out;
  std::vector<std::array<std::vector<std::pair<GO, double>>, 3>> rel(constraints.size());
  for (size_t s = 0; s < constraints.size(); ++s) {
    const SlaveProjection& g = constraints[s].geometry;
    for (int d = 0; d < 3; ++d) {
      const long long ds = dofs.dof(g.slaveNode, d);
      if (ds >= 0) rel[s][d].push_back({GO(ds), 1.0});
      for (size_t i = 0; i < g.masterNodes.size(); ++i) {
        const long long dm = dofs.dof(g.masterNodes[i], d);
        if (dm >= 0 && g.weights[i] != 0.0) rel[s][d].push_back({GO(dm), -g.weights[i]});
      }
      for (const auto& e : rel[s][d]) out.dofs.push_back(e.first);
    }
  }
  std::sort(out.dofs.begin(), out.dofs.end());
  out.dofs.erase(std::unique(out.dofs.begin(), out.dofs.end()), out.dofs.end());
  out.terms.resize(constraints.size());
  for (size_t s = 0; s < constraints.size(); ++s)
    for (int d = 0; d < 3; ++d)
      for (const auto& [dof, w] : rel[s][d])
        out.terms[s][d].push_back(
            {int(std::lower_bound(out.dofs.begin(), out.dofs.end(), dof) - out.dofs.begin()), w});
  return out;
}

}  // namespace

std::vector<char> contactSurfaceNodes(const ContactManager& contact, const Mesh& mesh) {
  std::vector<char> flags(mesh.numNodes(), 0);
  for (int p = 0; p < contact.numPairs(); ++p) {
    const PairDefinition& pair = contact.pair(p);
    for (const std::string& set : {pair.slaveNodeSet, pair.masterNodeSet})
      if (const NodeSet* ns = set.empty() ? nullptr : mesh.findNodeSet(set))
        for (int n : ns->nodes) flags[n] = 1;
    for (const std::string& name : {pair.masterSideSet, pair.slaveSideSet}) {
      const SideSet* ss = mesh.findSideSet(name);  // checked by the pairing
      for (size_t k = 0; ss && k < ss->elements.size(); ++k)
        for (int n : mesh.sideNodes(ss->elements[k], ss->sides[k])) flags[n] = 1;
    }
  }
  return flags;
}

// Constraint s: B_s u = n . (u_s - sum_i w_i u_i) over the slave node and the master face's
// nodes, or a mortar gap's derivative (SlaveProjection::gapGradient). allComponents keeps every component of the slave node even where n is zero (curved
// obstacles, whose normal turns: the matrix graph must hold every coupling).
ContactConstraint makeContactConstraint(const Point3& reference, const DofMap& dofs,
                                 const SlaveProjection& sp, bool allComponents) {
  ContactConstraint c;
  c.geometry = sp;
  c.owner = dofs.ownerOfNode(sp.slaveNode);
  c.reference = reference;
  std::vector<std::pair<GO, double>> t;
  for (const auto& [node, g] : sp.gapGradient)
    for (int d = 0; d < 3; ++d) {
      const long long dof = dofs.dof(node, d);
      if (dof >= 0 && (g[d] != 0.0 || allComponents)) t.push_back({GO(dof), g[d]});
    }
  for (int d = 0; d < 3 && sp.gapGradient.empty(); ++d) {
    const double n = sp.normal[d];
    if (std::abs(n) < 1e-14 && !allComponents) continue;
    const long long ds = dofs.dof(sp.slaveNode, d);
    if (ds >= 0) t.push_back({GO(ds), n});
    for (size_t i = 0; i < sp.masterNodes.size(); ++i) {
      const long long dm = dofs.dof(sp.masterNodes[i], d);
      if (dm >= 0 && (sp.weights[i] != 0.0 || allComponents)) t.push_back({GO(dm), -sp.weights[i] * n});
    }
  }
  std::sort(t.begin(), t.end());
  for (const auto& e : t) {  // merge repeated DOFs
    if (!c.terms.empty() && c.terms.back().first == e.first) c.terms.back().second += e.second;
    else c.terms.push_back(e);
  }
  if (sp.masterNodes.empty())  // an obstacle: the terms are the slave node's components
    for (int d = 0; d < 3; ++d) {
      const long long ds = dofs.dof(sp.slaveNode, d);
      for (size_t k = 0; ds >= 0 && k < c.terms.size(); ++k)
        if (c.terms[k].first == GO(ds)) c.componentTerm[d] = int(k);
    }
  return c;
}

ContactManager::~ContactManager() = default;

ContactManager::ContactManager(const Mesh& mesh, const DofMap& dofs, RCP<const Map> map,
                               const std::vector<PairDefinition>& pairs,
                               std::unique_ptr<ContactMethod> method)
    : pairs_(pairs), method_(std::move(method)), map_(std::move(map)) {
  for (size_t p = 0; p < pairs_.size(); ++p) {
    PairingResult res;
    try {
      res = pairs_[p].hasObstacle ? pairNodeToObstacle(mesh, pairs_[p], static_cast<int>(p))
            : !pairs_[p].masterNodeSet.empty() ? pairNodeToNode(mesh, pairs_[p], static_cast<int>(p))
            : pairs_[p].mortar                 ? pairMortar(mesh, pairs_[p], static_cast<int>(p))
                                               : pairNodeToFace(mesh, pairs_[p], static_cast<int>(p));
    } catch (const std::exception& e) {
      throw PairingError(int(p), "contact pair '" + pairs_[p].name + "': " + e.what());
    }
    hasObstacles_ = hasObstacles_ || pairs_[p].hasObstacle;
    hasCurvedObstacles_ = hasCurvedObstacles_ ||
                          (pairs_[p].hasObstacle && pairs_[p].obstacle.shape != RigidObstacle::Shape::Plane);
    unpaired_ += static_cast<int>(res.unpaired.size());
    // Curved obstacles and followed surfaces turn their normals: every component is a term.
    // Friction acts along every component of the slave and master nodes.
    const bool allComponents = pairs_[p].followMotion || pairs_[p].friction > 0 ||
        (pairs_[p].hasObstacle && pairs_[p].obstacle.shape != RigidObstacle::Shape::Plane);
    for (const SlaveProjection& sp : res.projections)
      constraints_.push_back(makeContactConstraint(mesh.coords[sp.slaveNode], dofs, sp, allComponents));
  }
  dofs_ = &dofs;
  if (hasObstacles_) slaveSize_ = slaveFaceSizes(mesh, pairs_, constraints_);
  for (const PairDefinition& pair : pairs_)
    if (pair.friction > 0 && !friction_)
      friction_ = std::make_unique<CoulombFriction>(
          CoulombFriction::Geometry{constraints_, pairs_, contactDofs_, dofs, map_, set_, *method_});
  indexTerms();
  slipTerms_ = slipTermsOf(constraints_, dofs);
  set_.status.assign(constraints_.size(), 0);
  set_.lambda.assign(constraints_.size(), 0.0);
  slip_.assign(constraints_.size(), 0.0);
  slipStart_.assign(constraints_.size(), Vec3{0, 0, 0});
  followed_ = std::make_unique<FollowedSurfaces>(mesh, dofs, pairs_);
  if (followed_->empty()) followed_.reset();
  set_.commit();
}

// contactDofs_ and localTerms_ from the constraints' terms.
void ContactManager::indexTerms() {
  contactDofs_.clear();
  localTerms_.clear();
  for (const auto& c : constraints_)
    for (const auto& t : c.terms) contactDofs_.push_back(t.first);
  std::sort(contactDofs_.begin(), contactDofs_.end());
  contactDofs_.erase(std::unique(contactDofs_.begin(), contactDofs_.end()), contactDofs_.end());
  for (const auto& c : constraints_) {
    std::vector<std::pair<int, double>> lt;
    for (const auto& t : c.terms)
      lt.push_back({int(std::lower_bound(contactDofs_.begin(), contactDofs_.end(), t.first) -
                        contactDofs_.begin()),
                    t.second});
    localTerms_.push_back(lt);
  }
  if (friction_) friction_->index();
}

std::vector<double> ContactManager::contactValues(const Vector& u) const {
  return gatherReplicated(*map_, contactDofs_, u);
}

std::vector<double> gatherReplicated(const Map& map, const std::vector<GO>& dofs, const Vector& u) {
  const size_t n = dofs.size();
  std::vector<double> mine(n, 0.0), all(n, 0.0);
  auto data = u.getData();
  for (size_t k = 0; k < n; ++k) {
    const LO l = map.getLocalElement(dofs[k]);
    if (l != Teuchos::OrdinalTraits<LO>::invalid()) mine[k] = data[l];
  }
  if (n > 0)
    Teuchos::reduceAll<int, double>(*map.getComm(), Teuchos::REDUCE_SUM, int(n), mine.data(), all.data());
  return all;
}

std::vector<double> ContactManager::gaps(const Vector& u) const { return gapsAt(contactValues(u)); }

std::vector<double> ContactManager::gapsAt(const std::vector<double>& x) const {
  std::vector<double> g(constraints_.size());
  for (size_t s = 0; s < constraints_.size(); ++s) {
    double v = constraints_[s].geometry.gap0;
    for (const auto& [k, coeff] : localTerms_[s]) v += coeff * x[k];
    g[s] = v;
  }
  return g;
}

std::vector<double> ContactManager::gapRates(const Vector& v) const {
  const std::vector<double> x = contactValues(v);
  std::vector<double> r(constraints_.size());
  for (size_t s = 0; s < constraints_.size(); ++s) {
    double rate = 0.0;
    for (const auto& [k, coeff] : localTerms_[s]) rate += coeff * x[k];
    const PairDefinition& pair = pairs_[constraints_[s].geometry.pair];
    if (pair.hasObstacle) rate -= dot(constraints_[s].geometry.normal, pair.obstacle.velocity);
    r[s] = rate;
  }
  return r;
}

std::vector<double> ContactManager::forces(const Vector& u) const {
  const std::vector<double> g = gaps(u);
  std::vector<double> f(g.size());
  for (size_t s = 0; s < g.size(); ++s) f[s] = method_->force(g[s], set_.lambda[s], set_.status[s]);
  return f;
}

double ContactManager::addForces(const Vector& u, Vector& out) {
  const std::vector<double> x = contactValues(u);
  const std::vector<double> g = gapsAt(x);
  auto data = out.getDataNonConst();
  const int rank = map_->getComm()->getRank();
  double local = 0.0;
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const double f = method_->force(g[s], set_.lambda[s], set_.status[s]);
    if (f != 0.0)
      for (const auto& [dof, coeff] : constraints_[s].terms) {
        const LO l = map_->getLocalElement(dof);
        if (l != Teuchos::OrdinalTraits<LO>::invalid()) data[l] -= f * coeff;
      }
    if (method_->hasMultipliers() && constraints_[s].owner == rank) {
      const double r = set_.rowResidual(s, g[s]);
      local += r * r;
    }
  }
  if (friction_) friction_->addForces(x, g, out);
  double global = 0.0;
  Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

std::vector<double> ContactManager::slips(const Vector& u, double t) const {
  const std::vector<double> x = gatherReplicated(*map_, slipTerms_.dofs, u);
  std::vector<double> out(constraints_.size(), 0.0);
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const SlaveProjection& g = constraints_[s].geometry;
    const PairDefinition& pair = pairs_[g.pair];
    Vec3 d{0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      for (const auto& [k, w] : slipTerms_.terms[s][c]) d[c] += w * x[k];
      if (pair.hasObstacle) d[c] -= pair.obstacle.velocity[c] * t;  // relative to the obstacle
    }
    const double dn = dot(d, g.normal);
    for (int c = 0; c < 3; ++c) d[c] -= dn * g.normal[c];
    out[s] = followed_ && followed_->follows(g.pair) ? slip_[s] : norm(d);
  }
  return out;
}

void ContactManager::beginStep(const Vector& u, double t, double dt) {
  if (followed_) followSurfaces(u);
  if (hasObstacles_) placeObstacles(u, t);
  if (friction_) friction_->beginStep(t, dt, [&] { return contactValues(u); });
}

void ContactManager::placeObstacles(const Vector& u, double t) {
  // A plane's constraint is exact and does not depend on u: (X + u - p(t)) . n - n . u. Only
  // curved obstacles need the nodes' current positions (a collective gather).
  const std::vector<double> x = hasCurvedObstacles_ ? contactValues(u) : std::vector<double>();
  bool turned = false;
  for (size_t s = 0; s < constraints_.size(); ++s) {
    ContactConstraint& c = constraints_[s];
    const PairDefinition& pair = pairs_[c.geometry.pair];
    if (!pair.hasObstacle) continue;
    if (pair.obstacle.shape == RigidObstacle::Shape::Plane) {
      c.geometry.gap0 = distanceTo(pair.obstacle, c.reference, t).gap;
      continue;
    }
    Point3 pos = c.reference;
    Vec3 us{0, 0, 0};
    for (int d = 0; d < 3; ++d)
      if (c.componentTerm[d] >= 0) {
        us[d] = x[localTerms_[s][c.componentTerm[d]].first];
        pos[d] += us[d];
      }
    ObstacleDistance od;
    try {
      od = distanceTo(pair.obstacle, pos, t);
    } catch (const std::invalid_argument& e) {
      throw NumericalError(format("contact pair '%s': node %d at t = %.6e s: %s", pair.name.c_str(),
                                  c.geometry.slaveNode + 1, t, e.what()));
    }
    double nu = 0.0;
    for (int d = 0; d < 3; ++d) {
      const int k = c.componentTerm[d];
      if (k < 0) continue;
      nu += od.normal[d] * us[d];
      if (c.terms[k].second != od.normal[d]) turned = true;
      c.terms[k].second = od.normal[d];
      localTerms_[s][k].second = od.normal[d];
    }
    c.geometry.normal = od.normal;
    c.geometry.gap0 = od.gap - nu;
  }
  if (turned) ++geometryVersion_;
}

void ContactManager::archive(StateArchive& a) const {
  set_.archive(a);
  if (followed_) a.putVector("contact/slip", slip_);
  if (followed_) archivePairing(a);
  if (friction_) friction_->archive(a);
}

void ContactManager::restore(const StateArchive& a) {
  set_.restore(a, constraints_.size());
  if (followed_) slip_ = a.getVector<double>("contact/slip", constraints_.size());
  if (followed_) restorePairing(a);
  if (friction_) friction_->restore(a);
  ++set_.version;
  set_.commit();
}

std::string ContactManager::activeSummary() const {
  std::vector<int> active(pairs_.size(), 0), all(pairs_.size(), 0);
  for (size_t s = 0; s < constraints_.size(); ++s) {
    ++all[constraints_[s].geometry.pair];
    active[constraints_[s].geometry.pair] += set_.status[s] ? 1 : 0;
  }
  std::string out;
  for (size_t p = 0; p < pairs_.size(); ++p)
    out += (out.empty() ? "" : ", ") + format("pair '%s': %d of %d nodes in contact", pairs_[p].name.c_str(),
                                              active[p], all[p]);
  return out;
}

double ContactManager::energy(const Vector& u) const {
  const std::vector<double> g = gaps(u);
  double e = 0.0;
  for (size_t s = 0; s < g.size(); ++s) e += method_->energy(g[s], set_.lambda[s], set_.status[s]);
  return e + (friction_ ? friction_->stickEnergy() : 0.0);
}

}  // namespace choc
