#include "physics/ModalLinks.hpp"

#include <cmath>
#include <sstream>

#include <Tpetra_MultiVector.hpp>

#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Vector3.hpp"
#include "core/Format.hpp"

namespace choc {

ModalLinks::ModalLinks(std::vector<ShockLink> links, const Model& model, const ModalBasis& basis)
    : ShockLinkSet(std::move(links)) {
  modes_ = static_cast<int>(basis.eigenvalues.size());
  for (const ShockLink& l : links_) {
    std::vector<long long> dofs;
    for (int c : {DX, DY, DZ}) dofs.push_back(model.dof(l.node1, c));
    for (int c : {DX, DY, DZ}) dofs.push_back(l.node2 >= 0 ? model.dof(l.node2, c) : -1);
    const std::vector<double> rows = gatherRows(*basis.vectors, dofs);
    phi1_.emplace_back(rows.begin(), rows.begin() + 3 * modes_);
    phi2_.emplace_back(rows.begin() + 3 * modes_, rows.end());
    hasRigid_ = hasRigid_ || l.law.rigid;
  }
  constraintForce_.assign(modes_, 0.0);
}

Vec3 ModalLinks::relative(size_t i, const std::vector<double>& x, bool position) const {
  const ShockLink& l = links_[i];
  Vec3 d{0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    double s = 0.0;
    const double* p1 = &phi1_[i][c * modes_];
    const double* p2 = &phi2_[i][c * modes_];
    for (int k = 0; k < modes_; ++k) s += (p2[k] - p1[k]) * x[k];
    d[c] = s + (position ? l.x2[c] - l.x1[c] : 0.0);
  }
  return d;
}

void ModalLinks::evaluate(double, const std::vector<double>& q, const std::vector<double>& v,
                          double dt, std::vector<double>& f) {
  std::fill(f.begin(), f.end(), 0.0);
  for (size_t i = 0; i < links_.size(); ++i) {
    ShockLink& l = links_[i];
    const Vec3 d = relative(i, q, true), w = relative(i, v, false);
    recordKinematics(i, d, w);
    if (l.law.rigid) continue;  // enforced in project(); l.last was set there
    const bool wasClosed = l.last.closed;
    l.last = evaluateShock(l.law, d, w, dt, l.state, true);
    // f_q = Phi2^T F - Phi1^T F
    for (int c = 0; c < 3; ++c) {
      const double F = l.last.forceOnNode2[c];
      if (F == 0.0) continue;
      const double* p1 = &phi1_[i][c * modes_];
      const double* p2 = &phi2_[i][c * modes_];
      for (int k = 0; k < modes_; ++k) f[k] += (p2[k] - p1[k]) * F;
    }
    accumulateDissipation(i, wasClosed, w, dt);
    if (l.law.tangential()) accumulateTangentialPower(i, w, dt);
  }
}

bool ModalLinks::nearContact(double dt) const {
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockLink& l = links_[i];
    if (l.last.closed) return true;
    // Could close within two steps at a closing speed of at least the last gap rate.
    if (l.last.gap <= 2.0 * dt * std::abs(lastGapRate_[i]) + 1e-15) return true;
  }
  return false;
}

void ModalLinks::generalizedDirection(size_t i, const Vec3& m, std::vector<double>& b) const {
  b.assign(modes_, 0.0);
  for (int c = 0; c < 3; ++c) {
    if (m[c] == 0.0) continue;
    const double* p1 = &phi1_[i][c * modes_];
    const double* p2 = &phi2_[i][c * modes_];
    for (int k = 0; k < modes_; ++k) b[k] += (p2[k] - p1[k]) * m[c];
  }
}

void ModalLinks::project(double h, std::vector<double>& q, std::vector<double>& v) {
  std::vector<double> b;
  std::fill(constraintForce_.begin(), constraintForce_.end(), 0.0);
  for (size_t i = 0; i < links_.size(); ++i) {
    ShockLink& l = links_[i];
    if (!l.law.rigid) continue;
    // lambda_n >= 0 such that gap(q_{n+1}) >= 0, lambda gap = 0. The gap is linear in q along
    // a fixed normal (planes); curved shapes converge in a few Newton-like passes.
    double lambda = 0.0;
    if (l.law.shape == ObstacleShape::BiCercInt && l.law.dist2 - l.law.dist1 <= 0.0) {
      // No free play: the inner circle cannot move in the plane orthogonal to the axis, a
      // bilateral tie d.e2 = d.e3 = 0 (the radial normal is undefined at r = 0).
      Vec3 force{0, 0, 0};
      for (int pass = 0; pass < 2; ++pass)
        for (const Vec3* e : {&l.law.frame.e2, &l.law.frame.e3}) {
          generalizedDirection(i, *e, b);
          double w = 0.0;
          for (double x : b) w += x * x;
          if (!(w > 0)) continue;
          const double dl = -dot(relative(i, q, true), *e) / (h * h * w);
          for (int k = 0; k < modes_; ++k) {
            q[k] += h * h * dl * b[k];
            v[k] += h * dl * b[k];
            constraintForce_[k] += dl * b[k];
          }
          for (int c = 0; c < 3; ++c) force[c] += dl * (*e)[c];
        }
      const Vec3 d = relative(i, q, true);
      l.last = ShockResponse{};
      l.last.gap = -std::sqrt(std::pow(dot(d, l.law.frame.e2), 2) + std::pow(dot(d, l.law.frame.e3), 2));
      l.last.forceOnNode2 = force;
      l.last.normalForce = std::sqrt(dot(force, force));
      l.last.closed = true;
      continue;
    }
    ShockGeometry g = shockGeometry(l.law, relative(i, q, true));
    for (int pass = 0; pass < 4 && g.gap < 0.0; ++pass) {
      generalizedDirection(i, g.normal, b);
      double w = 0.0;
      for (double x : b) w += x * x;
      if (!(w > 0)) break;  // the basis cannot move the link: nothing to enforce
      const double dl = -g.gap / (h * h * w);
      for (int k = 0; k < modes_; ++k) {
        q[k] += h * h * dl * b[k];
        v[k] += h * dl * b[k];
        constraintForce_[k] += dl * b[k];
      }
      lambda += dl;
      g = shockGeometry(l.law, relative(i, q, true));
      if (std::abs(g.gap) <= 1e-14 * (l.law.dist1 + l.law.dist2 + 1e-12)) break;
    }
    l.last = ShockResponse{};
    l.last.gap = g.gap;
    l.last.normalForce = lambda;
    l.last.closed = lambda > 0.0;
    for (int c = 0; c < 3; ++c) l.last.forceOnNode2[c] = lambda * g.normal[c];
  }
}

double ModalLinks::linkOmega2Bound() const {
  double s = 0.0;
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockLink& l = links_[i];
    if (l.law.rigid) continue;  // a constraint adds no frequency to the explicit scheme
    double flex = 0.0;
    for (int k = 0; k < modes_; ++k) {
      double dk2 = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double d = phi2_[i][c * modes_ + k] - phi1_[i][c * modes_ + k];
        dk2 += d * d;
      }
      flex += dk2;
    }
    s += std::max(l.law.normalStiffness, l.law.tangentialStiffness) * flex;  // normal or tangential
  }
  return s;
}

double ModalLinks::linkDampingRatioBound() const {
  double xi = 0.0;
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockLink& l = links_[i];
    if (l.law.rigid) continue;  // no dashpot in the rigid law
    double flex = 0.0;
    for (int k = 0; k < modes_; ++k)
      for (int c = 0; c < 3; ++c) {
        const double d = phi2_[i][c * modes_ + k] - phi1_[i][c * modes_ + k];
        flex += d * d;
      }
    // Effective mass m = 1/flex; xi = C / (2 sqrt(K m)).
    if (flex > 0 && l.law.normalStiffness > 0)
      xi = std::max(xi, std::max(l.law.normalDamping, l.law.tangentialDamping) /
                            (2.0 * std::sqrt(std::max(l.law.normalStiffness, l.law.tangentialStiffness) / flex)));
  }
  return xi;
}

void ModalLinks::archive(StateArchive& a) const {
  archiveLinks(a);
  a.putVector("links/constraintForce", constraintForce_);
}

void ModalLinks::restore(const StateArchive& a) {
  restoreLinks(a);
  constraintForce_ = a.getVector<double>("links/constraintForce", constraintForce_.size());
}

}  // namespace choc
