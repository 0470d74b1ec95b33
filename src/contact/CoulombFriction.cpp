// Coulomb friction of the contact pairs (CoulombFriction.hpp): the implicit law (the elastic-plastic
// law of the shock links, contact/ShockLaw.cpp, written on the relative motion of a slave node and
// its master point, with its consistent tangent) and the explicit forward increments (the
// tangential counterpart of the forward-increment pressures, Carpenter, Taylor and Katona 1991: at
// each sub-step, after the normal pressures lambda_s, each active node with friction gets the
// tangential force F_s that stops its relative tangential motion over the next sub-step (stick),
// unless that needs more than mu lambda_s; then F_s = mu lambda_s against the predicted motion
// (slip). The forces solve, by projected Gauss-Seidel as the pressures do (one sweep against
// obstacles),
//   delta_s = P_s (r_s(uStar) - r_s(u)) + h2 sum_k c_sk^2 w_k F_s + (the other nodes' forces on
//   shared master nodes),   F_s = -delta_s / d_s while |F_s| <= mu lambda_s,
// r_s = u_s - sum_i w_i u_i, P_s = I - n_s n_s^T, w the inverse lumped masses. The work of the
// forces, -1/2 (F_prev + F) . P (r(u) - r(u_prev)) on each sub-step's relative motion
// (trapezoidal, as the loads' work), is dissipated; no stick spring stores energy).
#include "contact/CoulombFriction.hpp"

#include <algorithm>
#include <cmath>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {
Vec3 sum(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scaled(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
}  // namespace

CoulombFriction::CoulombFriction(Geometry g) : g_(std::move(g)), pairWork_(g_.pairs.size(), 0.0) {}

double CoulombFriction::stickEnergy() const {
  if (!(kt_ > 0) || increments_) return 0.0;
  double e = 0.0;
  for (const Vec3& f : accepted_) e += dot(f, f) / (2.0 * kt_);
  return e;
}

// The relative-motion terms of every constraint (all components of the slave node and of its
// master face's nodes: the pairs with friction keep them all in the constraint's terms).
void CoulombFriction::index() {
  const size_t n = g_.constraints.size();
  rel_.assign(n, {});
  auto add = [&](size_t s, int node, double w) {
    for (int d = 0; d < 3; ++d) {
      const long long dof = g_.dofs.dof(node, d);
      if (dof < 0) continue;
      auto it = std::lower_bound(g_.contactDofs.begin(), g_.contactDofs.end(), GO(dof));
      if (it == g_.contactDofs.end() || *it != GO(dof)) continue;
      rel_[s].push_back({int(it - g_.contactDofs.begin()), d, w, GO(dof)});
    }
  };
  for (size_t s = 0; s < n; ++s) {
    const SlaveProjection& g = g_.constraints[s].geometry;
    add(s, g.slaveNode, 1.0);
    for (size_t i = 0; i < g.masterNodes.size(); ++i)
      if (g.weights[i] != 0.0) add(s, g.masterNodes[i], -g.weights[i]);
  }
  if (accepted_.size() != n) {
    accepted_.assign(n, Vec3{0, 0, 0});
    start_.assign(n, Vec3{0, 0, 0});
    acceptedStatus_.assign(n, 0);
    point_.assign(n, CoulombPoint{});
    normalForce_.assign(n, 0.0);
    lastDirection_.assign(n, Vec3{0, 0, 0});
    reversals_.assign(n, 0);
  }
}

// r(u) of constraint s at time t, from the values x at contactDofs_.
Vec3 CoulombFriction::relativeMotion(int s, const std::vector<double>& x, double t) const {
  Vec3 r{0, 0, 0};
  for (const auto& term : rel_[s]) r[term.component] += term.coeff * x[term.k];
  const PairDefinition& pair = g_.pairs[g_.constraints[s].geometry.pair];
  if (pair.hasObstacle)
    for (int d = 0; d < 3; ++d) r[d] -= pair.obstacle.velocity[d] * t;
  return r;
}


// The return mapping of every active node at the values x (gaps g): force, status, and for a
// sliding node the trial force's direction and size and the normal force.
void CoulombFriction::evaluate(const std::vector<double>& x, const std::vector<double>& g) {
    ++evaluations_;
  for (size_t s = 0; s < g_.constraints.size(); ++s) {
    CoulombPoint& p = point_[s];
    p.status = 0;
    p.force = Vec3{0, 0, 0};
    const double mu = g_.pairs[g_.constraints[s].geometry.pair].friction;
    if (!g_.set.status[s] || !(mu > 0)) continue;
    const double fn = g_.method.force(g[s], g_.set.lambda[s], true);
    if (!(fn > 0)) continue;  // a tensile iterate: the node is about to leave
    const Vec3 r = relativeMotion(int(s), x, time_);
    const Vec3 direction = p.direction;
    p = coulombTrial(accepted_[s], r - start_[s], g_.constraints[s].geometry.normal, kt_);
    p.direction = direction;
    const bool reversed = p.trialNorm > mu * fn && dot(p.trial, lastDirection_[s]) < 0.0 && reversals_[s] < 2;
    coulombReturn(p, mu, fn, reversed);
    if (reversed) {
      ++reversals_[s];
      lastDirection_[s] = Vec3{p.trial[0] / p.trialNorm, p.trial[1] / p.trialNorm, p.trial[2] / p.trialNorm};
    }
    if (p.status != 2) continue;
    normalForce_[s] = fn;
    lastDirection_[s] = p.direction;
  }
}


void CoulombFriction::addForces(const std::vector<double>& x, const std::vector<double>& g,
                                       Vector& out) {
  evaluate(x, g);
  auto data = out.getDataNonConst();
  for (size_t s = 0; s < g_.constraints.size(); ++s) {
    const CoulombPoint& p = point_[s];
    if (!p.status) continue;
    for (const auto& term : rel_[s]) {
      const LO l = g_.map->getLocalElement(term.dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) data[l] -= p.force[term.component] * term.coeff;
    }
  }
}


std::vector<char> CoulombFriction::key() const {
  std::vector<char> key;
  for (const CoulombPoint& p : point_) key.push_back(char(p.status));
  if (std::find(key.begin(), key.end(), 2) != key.end()) {
    const char* b = reinterpret_cast<const char*>(&evaluations_);
    key.insert(key.end(), b, b + sizeof evaluations_);
  }
  return key;
}


// Row a, column b: -d(residual force of a)/du_b. Stick: k_t c_a c_b P_ab. Slip:
// c_a c_b mu f_N k_t / |F*| (P - t t^T)_ab, plus the normal force's variation along t
// (mu k c_a t_a B_b for f_N = lambda - k g, and -mu c_a t_a S in lambda / S's column).
std::vector<MatrixEntry> CoulombFriction::tangent(GO multiplierBase) const {
  std::vector<MatrixEntry> out;
  const double k = g_.method.stiffness();
  for (size_t s = 0; s < g_.constraints.size(); ++s) {
    const CoulombPoint& p = point_[s];
    if (!p.status) continue;
    const Vec3& n = g_.constraints[s].geometry.normal;
    const Vec3& t = p.direction;
    const double mu = g_.pairs[g_.constraints[s].geometry.pair].friction;
    const bool slip = p.status == 2;
    const double scale = coulombTangentScale(p, kt_, mu, normalForce_[s]);
    for (const auto& a : rel_[s]) {
      if (g_.map->getLocalElement(a.dof) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      for (const auto& b : rel_[s]) {
        const double q = coulombProjector(p, n, a.component, b.component);
        if (q != 0.0) out.push_back({a.dof, b.dof, scale * a.coeff * b.coeff * q});
      }
      if (!slip) continue;
      if (k != 0.0)
        for (const auto& [dof, B] : g_.constraints[s].terms)
          out.push_back({a.dof, dof, mu * k * a.coeff * t[a.component] * B});
      if (g_.method.hasMultipliers())
        out.push_back({a.dof, multiplierBase + GO(s), -mu * a.coeff * t[a.component] * g_.set.scale});
    }
  }
  return out;
}


// Before a step to t of length dt: r(u_n) for the step's relative motion, and the accepted
// forces in the (possibly turned) tangent planes.
void CoulombFriction::beginStep(double t, double dt, const std::function<std::vector<double>()>& startValues) {
    if (increments_) {  // explicit: the forces are decided by increment()
    time_ = t;
    return;
  }
  const std::vector<double> x = startValues();
  time_ = t;
  for (size_t s = 0; s < g_.constraints.size(); ++s) {
    start_[s] = relativeMotion(int(s), x, t - dt);
    accepted_[s] = inPlane(accepted_[s], g_.constraints[s].geometry.normal);
    lastDirection_[s] = Vec3{0, 0, 0};
    reversals_[s] = 0;
  }
}


// An accepted step: the forces at u become the accepted ones, and the friction work less what
// the stick springs store is dissipated (trapezoidal rule on the step's relative motion).
void CoulombFriction::commitMotion(const std::function<std::vector<double>()>& values,
                                   const std::function<std::vector<double>(const std::vector<double>&)>& gaps) {
    if (increments_) return;  // explicit: accounted by increment()
  const std::vector<double> x = values();
  evaluate(x, gaps(x));
  for (size_t s = 0; s < g_.constraints.size(); ++s) {
    const Vec3& n = g_.constraints[s].geometry.normal;
    const Vec3 r = relativeMotion(int(s), x, time_);
    const Vec3 delta = inPlane(Vec3{r[0] - start_[s][0], r[1] - start_[s][1], r[2] - start_[s][2]}, n);
    const Vec3& before = accepted_[s];
    const Vec3& after = point_[s].force;
    const double work = -0.5 * (dot(before, delta) + dot(after, delta));
    const double stored = kt_ > 0 ? (dot(after, after) - dot(before, before)) / (2.0 * kt_) : 0.0;
    dissipated_ += work - stored;
    pairWork_[g_.constraints[s].geometry.pair] += work - stored;
    accepted_[s] = after;
    acceptedStatus_[s] = char(point_[s].status);
  }
}


// The tangential forces: for each active node (acts), F = -delta / d while |F| <= mu lambda, capped
// otherwise, delta its predicted relative tangential motion with the other nodes' forces, by
// projected Gauss-Seidel until no sweep moves a node by more than 1e-12 of scale.
std::vector<Vec3> CoulombFriction::tangentialForces(const std::vector<Vec3>& predicted, const std::vector<Vec3>& d,
                                                    const std::vector<char>& acts, const std::vector<double>& w,
                                                    double h2, double scale,
                                                    const std::function<std::string()>& where) const {
  const size_t nS = g_.constraints.size();
  std::vector<Vec3> F(nS, Vec3{0, 0, 0});
  std::vector<double> shift(w.size(), 0.0);  // h2 w_k sum of the forces' terms at each DOF
  const double tol = 1e-12 * scale;
  bool converged = false;
  int sweeps = 0;
  for (; sweeps < 1000 && !converged; ++sweeps) {
    double change = 0.0;
    for (size_t s = 0; s < nS; ++s) {
      if (!acts[s]) continue;
      const Vec3& n = g_.constraints[s].geometry.normal;
      Vec3 delta = predicted[s];
      for (const auto& t : rel_[s]) delta[t.component] += t.coeff * shift[t.k];
      delta = inPlane(delta, n);
      Vec3 next = F[s];
      for (int c = 0; c < 3; ++c)
        if (d[s][c] > 0) next[c] -= delta[c] / d[s][c];
      next = inPlane(next, n);
      const double limit = g_.pairs[g_.constraints[s].geometry.pair].friction * g_.set.lambda[s];
      const double size = norm(next);
      if (size > limit) next = scaled(limit / size, next);
      const Vec3 step = next - F[s];
      if (step[0] == 0.0 && step[1] == 0.0 && step[2] == 0.0) continue;
      for (const auto& t : rel_[s]) shift[t.k] += h2 * w[t.k] * t.coeff * step[t.component];
      for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(step[c]) * d[s][c]);
      F[s] = next;
    }
    converged = change <= tol;
  }
  if (!converged)
    throw NumericalError(format("forward-increment friction: the tangential forces did not converge in %d "
                                "sweeps (%s)", sweeps, where().c_str()));
  return F;
}


void CoulombFriction::increment(const std::vector<double>& x, const std::vector<double>& xStar, double h, double h2,
                                const std::vector<double>& w, const Vector& inverseMass, Vector& a,
                                const std::function<std::string()>& where) {
  const size_t nS = g_.constraints.size();
  // The work of the last sub-step's forces and of the new ones over the last sub-step's motion.
  std::vector<Vec3> r(nS), motion(nS, Vec3{0, 0, 0});
  for (size_t s = 0; s < nS; ++s) {
    r[s] = relativeMotion(int(s), x, time_);
    if (started_) motion[s] = inPlane(r[s] - start_[s], g_.constraints[s].geometry.normal);
  }
  std::vector<Vec3> d(nS, Vec3{0, 0, 0}), predicted(nS, Vec3{0, 0, 0});
  std::vector<char> acts(nS, 0);
  double scale = 0.0;
  for (size_t s = 0; s < nS; ++s) {
    const double mu = g_.pairs[g_.constraints[s].geometry.pair].friction;
    if (!(mu > 0) || !(g_.set.lambda[s] > 0)) continue;
    acts[s] = 1;
    for (const auto& t : rel_[s]) d[s][t.component] += h2 * t.coeff * t.coeff * w[t.k];
    const Vec3 rStar = relativeMotion(int(s), xStar, time_ + h);
    predicted[s] = inPlane(rStar - r[s], g_.constraints[s].geometry.normal);
    scale = std::max(scale, norm(predicted[s]));
  }
  const std::vector<Vec3> F = tangentialForces(predicted, d, acts, w, h2, scale, where);
  auto ad = a.getDataNonConst();
  auto wd = inverseMass.getData();
  for (size_t s = 0; s < nS; ++s) {
    const double limit = g_.pairs[g_.constraints[s].geometry.pair].friction * g_.set.lambda[s];
    if (started_) {
      const double work = -0.5 * dot(sum(accepted_[s], F[s]), motion[s]);
      dissipated_ += work;
      pairWork_[g_.constraints[s].geometry.pair] += work;
    }
    start_[s] = r[s];
    accepted_[s] = F[s];
    point_[s] = CoulombPoint{};
    point_[s].force = F[s];
    point_[s].status = acts[s] ? (norm(F[s]) < limit * (1.0 - 1e-12) ? 1 : 2) : 0;
    acceptedStatus_[s] = char(point_[s].status);
    if (!acts[s]) continue;
    for (const auto& t : rel_[s]) {
      const LO l = g_.map->getLocalElement(t.dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) ad[l] += wd[l] * F[s][t.component] * t.coeff;
    }
  }
  started_ = true;
}


void CoulombFriction::archive(StateArchive& a) const {
  std::vector<double> forces;
  for (const Vec3& v : accepted_) forces.insert(forces.end(), v.begin(), v.end());
  a.putVector("contact/friction", forces);
  a.putVector("contact/frictionStatus", acceptedStatus_);
  a.putDouble("contact/frictionWork", dissipated_);
  a.putVector("contact/pairFrictionWork", pairWork_);
  if (increments_ && started_) {  // the relative positions of the last increment
    std::vector<double> start;
    for (const Vec3& v : start_) start.insert(start.end(), v.begin(), v.end());
    a.putVector("contact/frictionStart", start);
  }
}

void CoulombFriction::restore(const StateArchive& a) {
  const size_t n = g_.constraints.size();
  const std::vector<double> forces = a.getVector<double>("contact/friction", 3 * n);
  for (size_t s = 0; s < n; ++s) accepted_[s] = Vec3{forces[3 * s], forces[3 * s + 1], forces[3 * s + 2]};
  acceptedStatus_ = a.getVector<char>("contact/frictionStatus", n);
  dissipated_ = a.getDouble("contact/frictionWork");
  pairWork_ = a.getVector<double>("contact/pairFrictionWork", g_.pairs.size());
  started_ = increments_ && a.has("contact/frictionStart");
  if (started_) {
    const std::vector<double> start = a.getVector<double>("contact/frictionStart", 3 * n);
    for (size_t s = 0; s < n; ++s) start_[s] = Vec3{start[3 * s], start[3 * s + 1], start[3 * s + 2]};
  }
}

}  // namespace choc
