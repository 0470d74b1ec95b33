// ContactManager: Coulomb friction of the contact pairs (see the header). The law is the
// elastic-plastic one of the shock links (contact/ShockLaw.cpp) written on the relative
// motion of a slave node and its master point, with its consistent tangent.
#include <algorithm>
#include <cmath>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "contact/CoulombLaw.hpp"
#include "contact/FrictionState.hpp"

namespace choc {

ContactManager::~ContactManager() = default;

void ContactManager::enableFriction() {
  friction_ = std::make_shared<Friction>();
  friction_->pairWork.assign(pairs_.size(), 0.0);
}

double ContactManager::frictionDissipation(int pair) const {
  return friction_ ? friction_->pairWork[pair] : 0.0;
}

void ContactManager::setTangentialStiffness(double kt) {
  if (friction_) friction_->kt = kt;
}
double ContactManager::tangentialStiffness() const { return friction_ ? friction_->kt : 0.0; }
const std::vector<Vec3>& ContactManager::frictionForces() const { return friction_->accepted; }
const std::vector<char>& ContactManager::frictionStatus() const { return friction_->acceptedStatus; }
double ContactManager::frictionDissipation() const { return friction_ ? friction_->dissipated : 0.0; }

double ContactManager::stickEnergy() const {
  if (!friction_ || !(friction_->kt > 0) || friction_->increments) return 0.0;
  double e = 0.0;
  for (const Vec3& f : friction_->accepted) e += dot(f, f) / (2.0 * friction_->kt);
  return e;
}

// The relative-motion terms of every constraint (all components of the slave node and of its
// master face's nodes: the pairs with friction keep them all in the constraint's terms).
void ContactManager::indexFriction() {
  if (!friction_) return;
  Friction& f = *friction_;
  const size_t n = constraints_.size();
  f.rel.assign(n, {});
  auto add = [&](size_t s, int node, double w) {
    for (int d = 0; d < 3; ++d) {
      const long long dof = dofs_->dof(node, d);
      if (dof < 0) continue;
      auto it = std::lower_bound(contactDofs_.begin(), contactDofs_.end(), GO(dof));
      if (it == contactDofs_.end() || *it != GO(dof)) continue;
      f.rel[s].push_back({int(it - contactDofs_.begin()), d, w, GO(dof)});
    }
  };
  for (size_t s = 0; s < n; ++s) {
    const SlaveProjection& g = constraints_[s].geometry;
    add(s, g.slaveNode, 1.0);
    for (size_t i = 0; i < g.masterNodes.size(); ++i)
      if (g.weights[i] != 0.0) add(s, g.masterNodes[i], -g.weights[i]);
  }
  if (f.accepted.size() != n) {
    f.accepted.assign(n, Vec3{0, 0, 0});
    f.start.assign(n, Vec3{0, 0, 0});
    f.acceptedStatus.assign(n, 0);
    f.point.assign(n, CoulombPoint{});
    f.normalForce.assign(n, 0.0);
    f.lastDirection.assign(n, Vec3{0, 0, 0});
    f.reversals.assign(n, 0);
  }
}

// r(u) of constraint s at time t, from the values x at contactDofs_.
Vec3 ContactManager::relativeMotion(int s, const std::vector<double>& x, double t) const {
  Vec3 r{0, 0, 0};
  for (const auto& term : friction_->rel[s]) r[term.component] += term.coeff * x[term.k];
  const PairDefinition& pair = pairs_[constraints_[s].geometry.pair];
  if (pair.hasObstacle)
    for (int d = 0; d < 3; ++d) r[d] -= pair.obstacle.velocity[d] * t;
  return r;
}

// The return mapping of every active node at the values x (gaps g): force, status, and for a
// sliding node the trial force's direction and size and the normal force.
void ContactManager::evaluateFriction(const std::vector<double>& x, const std::vector<double>& g) const {
  Friction& f = *friction_;
  ++f.evaluations;
  for (size_t s = 0; s < constraints_.size(); ++s) {
    CoulombPoint& p = f.point[s];
    p.status = 0;
    p.force = Vec3{0, 0, 0};
    const double mu = pairs_[constraints_[s].geometry.pair].friction;
    if (!set_.status[s] || !(mu > 0)) continue;
    const double fn = method_->force(g[s], set_.lambda[s], true);
    if (!(fn > 0)) continue;  // a tensile iterate: the node is about to leave
    const Vec3 r = relativeMotion(int(s), x, f.time);
    const Vec3 direction = p.direction;
    p = coulombTrial(f.accepted[s], r - f.start[s], constraints_[s].geometry.normal, f.kt);
    p.direction = direction;
    const bool reversed = p.trialNorm > mu * fn && dot(p.trial, f.lastDirection[s]) < 0.0 && f.reversals[s] < 2;
    coulombReturn(p, mu, fn, reversed);
    if (reversed) {
      ++f.reversals[s];
      f.lastDirection[s] = Vec3{p.trial[0] / p.trialNorm, p.trial[1] / p.trialNorm, p.trial[2] / p.trialNorm};
    }
    if (p.status != 2) continue;
    f.normalForce[s] = fn;
    f.lastDirection[s] = p.direction;
  }
}

void ContactManager::addFrictionForces(const std::vector<double>& x, const std::vector<double>& g,
                                       Vector& out) const {
  evaluateFriction(x, g);
  auto data = out.getDataNonConst();
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const CoulombPoint& p = friction_->point[s];
    if (!p.status) continue;
    for (const auto& term : friction_->rel[s]) {
      const LO l = map_->getLocalElement(term.dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) data[l] -= p.force[term.component] * term.coeff;
    }
  }
}

std::vector<char> ContactManager::frictionKey() const {
  if (!friction_) return {};
  std::vector<char> key;
  for (const CoulombPoint& p : friction_->point) key.push_back(char(p.status));
  if (std::find(key.begin(), key.end(), 2) != key.end()) {
    const char* b = reinterpret_cast<const char*>(&friction_->evaluations);
    key.insert(key.end(), b, b + sizeof friction_->evaluations);
  }
  return key;
}

// Row a, column b: -d(residual force of a)/du_b. Stick: k_t c_a c_b P_ab. Slip:
// c_a c_b mu f_N k_t / |F*| (P - t t^T)_ab, plus the normal force's variation along t
// (mu k c_a t_a B_b for f_N = lambda - k g, and -mu c_a t_a S in lambda / S's column).
std::vector<MatrixEntry> ContactManager::frictionTangent(GO multiplierBase) const {
  std::vector<MatrixEntry> out;
  if (!friction_) return out;
  const Friction& f = *friction_;
  const double k = method_->stiffness();
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const CoulombPoint& p = f.point[s];
    if (!p.status) continue;
    const Vec3& n = constraints_[s].geometry.normal;
    const Vec3& t = p.direction;
    const double mu = pairs_[constraints_[s].geometry.pair].friction;
    const bool slip = p.status == 2;
    const double scale = coulombTangentScale(p, f.kt, mu, f.normalForce[s]);
    for (const auto& a : f.rel[s]) {
      if (map_->getLocalElement(a.dof) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      for (const auto& b : f.rel[s]) {
        const double q = coulombProjector(p, n, a.component, b.component);
        if (q != 0.0) out.push_back({a.dof, b.dof, scale * a.coeff * b.coeff * q});
      }
      if (!slip) continue;
      if (k != 0.0)
        for (const auto& [dof, B] : constraints_[s].terms)
          out.push_back({a.dof, dof, mu * k * a.coeff * t[a.component] * B});
      if (method_->hasMultipliers())
        out.push_back({a.dof, multiplierBase + GO(s), -mu * a.coeff * t[a.component] * set_.scale});
    }
  }
  return out;
}

// Before a step to t of length dt: r(u_n) for the step's relative motion, and the accepted
// forces in the (possibly turned) tangent planes.
void ContactManager::beginFrictionStep(const Vector& u, double t, double dt) {
  Friction& f = *friction_;
  if (f.increments) {  // explicit: the forces are decided by frictionIncrement
    f.time = t;
    return;
  }
  const std::vector<double> x = contactValues(u);
  f.time = t;
  for (size_t s = 0; s < constraints_.size(); ++s) {
    f.start[s] = relativeMotion(int(s), x, t - dt);
    f.accepted[s] = inPlane(f.accepted[s], constraints_[s].geometry.normal);
    f.lastDirection[s] = Vec3{0, 0, 0};
    f.reversals[s] = 0;
  }
}

// An accepted step: the forces at u become the accepted ones, and the friction work less what
// the stick springs store is dissipated (trapezoidal rule on the step's relative motion).
void ContactManager::commitFriction(const Vector& u) {
  Friction& f = *friction_;
  if (f.increments) return;  // explicit: accounted by frictionIncrement
  const std::vector<double> x = contactValues(u);
  evaluateFriction(x, gapsAt(x));
  for (size_t s = 0; s < constraints_.size(); ++s) {
    const Vec3& n = constraints_[s].geometry.normal;
    const Vec3 r = relativeMotion(int(s), x, f.time);
    const Vec3 delta = inPlane(Vec3{r[0] - f.start[s][0], r[1] - f.start[s][1], r[2] - f.start[s][2]}, n);
    const Vec3& before = f.accepted[s];
    const Vec3& after = f.point[s].force;
    const double work = -0.5 * (dot(before, delta) + dot(after, delta));
    const double stored = f.kt > 0 ? (dot(after, after) - dot(before, before)) / (2.0 * f.kt) : 0.0;
    f.dissipated += work - stored;
    f.pairWork[constraints_[s].geometry.pair] += work - stored;
    f.accepted[s] = after;
    f.acceptedStatus[s] = char(f.point[s].status);
  }
}

void ContactManager::archiveFriction(StateArchive& a) const {
  if (!friction_) return;
  std::vector<double> forces;
  for (const Vec3& v : friction_->accepted) forces.insert(forces.end(), v.begin(), v.end());
  a.putVector("contact/friction", forces);
  a.putVector("contact/frictionStatus", friction_->acceptedStatus);
  a.putDouble("contact/frictionWork", friction_->dissipated);
  a.putVector("contact/pairFrictionWork", friction_->pairWork);
  if (friction_->increments && friction_->started) {  // the relative positions of the last increment
    std::vector<double> start;
    for (const Vec3& v : friction_->start) start.insert(start.end(), v.begin(), v.end());
    a.putVector("contact/frictionStart", start);
  }
}

void ContactManager::restoreFriction(const StateArchive& a) {
  if (!friction_) return;
  const size_t n = constraints_.size();
  const std::vector<double> forces = a.getVector<double>("contact/friction", 3 * n);
  for (size_t s = 0; s < n; ++s) friction_->accepted[s] = Vec3{forces[3 * s], forces[3 * s + 1], forces[3 * s + 2]};
  friction_->acceptedStatus = a.getVector<char>("contact/frictionStatus", n);
  friction_->dissipated = a.getDouble("contact/frictionWork");
  friction_->pairWork = a.getVector<double>("contact/pairFrictionWork", pairs_.size());
  friction_->started = friction_->increments && a.has("contact/frictionStart");
  if (friction_->started) {
    const std::vector<double> start = a.getVector<double>("contact/frictionStart", 3 * n);
    for (size_t s = 0; s < n; ++s) friction_->start[s] = Vec3{start[3 * s], start[3 * s + 1], start[3 * s + 2]};
  }
}

}  // namespace choc
