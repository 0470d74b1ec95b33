// Coulomb friction in explicit central differences, by forward increments (the tangential
// counterpart of the forward-increment pressures, Carpenter, Taylor and Katona 1991): at each
// sub-step, after the normal pressures lambda_s, each active node with friction gets the
// tangential force F_s that stops its relative tangential motion over the next sub-step
// (stick), unless that needs more than mu lambda_s; then F_s = mu lambda_s against the predicted
// motion (slip). The forces solve, by projected Gauss-Seidel as the pressures do (one sweep
// against obstacles),
//   delta_s = P_s (r_s(uStar) - r_s(u)) + h2 sum_k c_sk^2 w_k F_s + (the other nodes' forces on
//   shared master nodes),   F_s = -delta_s / d_s while |F_s| <= mu lambda_s,
// r_s = u_s - sum_i w_i u_i, P_s = I - n_s n_s^T, w the inverse lumped masses. The work of the
// forces, -1/2 (F_prev + F) . P (r(u) - r(u_prev)) on each sub-step's relative motion
// (trapezoidal, as the loads' work), is dissipated; no stick spring stores energy.
#include <algorithm>
#include <cmath>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "contact/FrictionState.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

void ContactManager::useForwardIncrements(bool on) {
  if (friction_) friction_->increments = on;
}

namespace {
Vec3 sum(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scaled(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
}  // namespace

// The tangential forces: for each active node (acts), F = -delta / d while |F| <= mu lambda, capped
// otherwise, delta its predicted relative tangential motion with the other nodes' forces, by
// projected Gauss-Seidel until no sweep moves a node by more than 1e-12 of scale.
std::vector<Vec3> ContactManager::tangentialForces(const std::vector<Vec3>& predicted, const std::vector<Vec3>& d,
                                                   const std::vector<char>& acts, double h2, double scale) const {
  const Friction& f = *friction_;
  const std::vector<double>& w = inverseMassAtContact_;
  const size_t nS = constraints_.size();
  std::vector<Vec3> F(nS, Vec3{0, 0, 0});
  std::vector<double> shift(w.size(), 0.0);  // h2 w_k sum of the forces' terms at each DOF
  const double tol = 1e-12 * scale;
  bool converged = false;
  int sweeps = 0;
  for (; sweeps < 1000 && !converged; ++sweeps) {
    double change = 0.0;
    for (size_t s = 0; s < nS; ++s) {
      if (!acts[s]) continue;
      const Vec3& n = constraints_[s].geometry.normal;
      Vec3 delta = predicted[s];
      for (const auto& t : f.rel[s]) delta[t.component] += t.coeff * shift[t.k];
      delta = inPlane(delta, n);
      Vec3 next = F[s];
      for (int c = 0; c < 3; ++c)
        if (d[s][c] > 0) next[c] -= delta[c] / d[s][c];
      next = inPlane(next, n);
      const double limit = pairs_[constraints_[s].geometry.pair].friction * set_.lambda[s];
      const double size = norm(next);
      if (size > limit) next = scaled(limit / size, next);
      const Vec3 step = next - F[s];
      if (step[0] == 0.0 && step[1] == 0.0 && step[2] == 0.0) continue;
      for (const auto& t : f.rel[s]) shift[t.k] += h2 * w[t.k] * t.coeff * step[t.component];
      for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(step[c]) * d[s][c]);
      F[s] = next;
    }
    converged = change <= tol;
  }
  if (!converged)
    throw NumericalError(format("forward-increment friction: the tangential forces did not converge in %d "
                                "sweeps (%s)", sweeps, activeSummary().c_str()));
  return F;
}

void ContactManager::frictionIncrement(const std::vector<double>& x, const std::vector<double>& xStar, double h,
                                       double h2, const Vector& inverseMass, Vector& a) {
  Friction& f = *friction_;
  const size_t nS = constraints_.size();
  const std::vector<double>& w = inverseMassAtContact_;
  // The work of the last sub-step's forces and of the new ones over the last sub-step's motion.
  std::vector<Vec3> r(nS), motion(nS, Vec3{0, 0, 0});
  for (size_t s = 0; s < nS; ++s) {
    r[s] = relativeMotion(int(s), x, f.time);
    if (f.started) motion[s] = inPlane(r[s] - f.start[s], constraints_[s].geometry.normal);
  }
  std::vector<Vec3> d(nS, Vec3{0, 0, 0}), predicted(nS, Vec3{0, 0, 0});
  std::vector<char> acts(nS, 0);
  double scale = 0.0;
  for (size_t s = 0; s < nS; ++s) {
    const double mu = pairs_[constraints_[s].geometry.pair].friction;
    if (!(mu > 0) || !(set_.lambda[s] > 0)) continue;
    acts[s] = 1;
    for (const auto& t : f.rel[s]) d[s][t.component] += h2 * t.coeff * t.coeff * w[t.k];
    const Vec3 rStar = relativeMotion(int(s), xStar, f.time + h);
    predicted[s] = inPlane(rStar - r[s], constraints_[s].geometry.normal);
    scale = std::max(scale, norm(predicted[s]));
  }
  const std::vector<Vec3> F = tangentialForces(predicted, d, acts, h2, scale);
  auto ad = a.getDataNonConst();
  auto wd = inverseMass.getData();
  for (size_t s = 0; s < nS; ++s) {
    const double limit = pairs_[constraints_[s].geometry.pair].friction * set_.lambda[s];
    if (f.started) {
      const double work = -0.5 * dot(sum(f.accepted[s], F[s]), motion[s]);
      f.dissipated += work;
      f.pairWork[constraints_[s].geometry.pair] += work;
    }
    f.start[s] = r[s];
    f.accepted[s] = F[s];
    f.point[s] = CoulombPoint{};
    f.point[s].force = F[s];
    f.point[s].status = acts[s] ? (norm(F[s]) < limit * (1.0 - 1e-12) ? 1 : 2) : 0;
    f.acceptedStatus[s] = char(f.point[s].status);
    if (!acts[s]) continue;
    for (const auto& t : f.rel[s]) {
      const LO l = map_->getLocalElement(t.dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) ad[l] += wd[l] * F[s][t.component] * t.coeff;
    }
  }
  f.started = true;
}

}  // namespace choc
