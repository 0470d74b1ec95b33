#include "physics/DirectLinks.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "fem/Components.hpp"

namespace choc {

namespace {

// Largest extent of the mesh along an axis [m].
double meshExtent(const Model& model) {
  const auto& X = model.mesh().coords;
  double extent = 0.0;
  for (int c = 0; c < 3; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& x : X) lo = std::min(lo, x[c]), hi = std::max(hi, x[c]);
    if (!X.empty()) extent = std::max(extent, hi - lo);
  }
  return extent;
}

bool curved(ObstacleShape s) { return s == ObstacleShape::BiCercle || s == ObstacleShape::BiCercInt; }

}  // namespace

DirectLinks::DirectLinks(std::vector<ShockLink> links, const Model& model, RCP<const Map> map)
    : ShockLinkSet(std::move(links)), map_(std::move(map)) {
  for (const ShockLink& l : links_) {
    if (l.law.rigid)
      throwInput(model.inputFile(), l.path + "/Normal Law", "rigid",
                 "is the modal transient's forward-increment constraint, not available in a direct transient",
                 "use 'penalty' with a stiffness, or a contact pair with the Lagrange method against the "
                 "node set");
    std::array<GO, 6> d{};
    for (int c = 0; c < 3; ++c) {
      d[c] = GO(model.dof(l.node1, DX + c));
      d[3 + c] = l.node2 >= 0 ? GO(model.dof(l.node2, DX + c)) : GO(-1);
    }
    dofs_.push_back(d);
  }
  step_ = 0;
  d_.assign(links_.size(), Vec3{0, 0, 0});
  w_.assign(links_.size(), Vec3{0, 0, 0});
  dPrev_.assign(links_.size(), Vec3{0, 0, 0});
  fdPrev_.assign(links_.size(), Vec3{0, 0, 0});
  ftPrev_.assign(links_.size(), Vec3{0, 0, 0});
  jacobian_.assign(links_.size(), std::array<double, 9>{});
  switches_.assign(links_.size(), 0);
  dashpotOff_.assign(links_.size(), 0);
  trial_.assign(links_.size(), ShockResponse{});
  length_ = meshExtent(model);
}

std::vector<std::vector<GO>> DirectLinks::couplings() const {
  std::vector<std::vector<GO>> groups;
  for (const auto& d : dofs_) {
    std::vector<GO> g;
    for (GO x : d)
      if (x >= 0) g.push_back(x);
    groups.push_back(g);
  }
  return groups;
}

void DirectLinks::beginStep(double dt) {
  dt_ = dt;
  ++step_;
  std::fill(switches_.begin(), switches_.end(), 0);
  std::fill(dashpotOff_.begin(), dashpotOff_.end(), 0);
}

ShockLawParameters DirectLinks::lawOfStep(size_t i) const {
  ShockLawParameters p = links_[i].law;
  if (dashpotOff_[i]) p.normalDamping = 0.0;
  return p;
}

Vec3 DirectLinks::force(size_t i, const Vec3& d, const Vec3& w) const {
  ShockLawState s = links_[i].state;
  return evaluateShock(lawOfStep(i), d, w, dt_, s, false).forceOnNode2;
}

void DirectLinks::addForces(const Vector& u, const Vector& v, Vector& out) {
  const size_t n = links_.size();
  // Every rank gets the links' nodal values: each owner contributes its own.
  std::vector<double> mine(12 * n, 0.0), all(12 * n, 0.0);
  {
    auto ud = u.getData();
    auto vd = v.getData();
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 6; ++k) {
        if (dofs_[i][k] < 0) continue;
        const LO l = map_->getLocalElement(dofs_[i][k]);
        if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
        mine[12 * i + k] = ud[l];
        mine[12 * i + 6 + k] = vd[l];
      }
  }
  if (n > 0)
    Teuchos::reduceAll<int, double>(*map_->getComm(), Teuchos::REDUCE_SUM, int(all.size()), mine.data(),
                                    all.data());
  auto od = out.getDataNonConst();
  for (size_t i = 0; i < n; ++i) {
    const ShockLink& l = links_[i];
    const double* x = &all[12 * i];
    for (int c = 0; c < 3; ++c) {
      d_[i][c] = (l.x2[c] + x[3 + c]) - (l.x1[c] + x[c]);
      w_[i][c] = x[9 + c] - x[6 + c];
    }
    ShockLawState s = l.state;
    const bool wasPressing = trial_[i].normalForce > 0.0;
    trial_[i] = evaluateShock(lawOfStep(i), d_[i], w_[i], dt_, s, false);
    // A dashpot makes the force jump where the link closes while approaching: the step may
    // have no solution there, and Newton alternates between open and pressing. After three
    // switches of the status in one step the step goes on without the dashpot (a continuous law).
    if (wasPressing != (trial_[i].normalForce > 0.0) && ++switches_[i] >= 3 && !dashpotOff_[i] &&
        l.law.normalDamping > 0.0) {
      dashpotOff_[i] = 1;
      ++dashpotDrops_;
      s = l.state;
      trial_[i] = evaluateShock(lawOfStep(i), d_[i], w_[i], dt_, s, false);
    }
    for (int k = 0; k < 6; ++k) {
      if (dofs_[i][k] < 0) continue;
      const LO r = map_->getLocalElement(dofs_[i][k]);
      if (r == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      const double F = trial_[i].forceOnNode2[k % 3];
      od[r] += k < 3 ? F : -F;  // the residual holds minus the force on each node
    }
  }
  pending_ = true;
}

std::vector<char> DirectLinks::tangentKey() const {
  std::vector<char> key;
  bool moving = false;
  for (size_t i = 0; i < links_.size(); ++i) {
    const bool pressing = trial_[i].normalForce > 0.0;  // closed and not clipped by the dashpot
    key.push_back(char(pressing) | char(trial_[i].sliding) << 1);
    moving = moving || (pressing && (curved(links_[i].law.shape) || trial_[i].sliding));
  }
  if (moving) {
    const char* b = reinterpret_cast<const char*>(&step_);
    key.insert(key.end(), b, b + sizeof step_);
  }
  return key;
}

std::vector<MatrixEntry> DirectLinks::tangent(double velocityFactor) {
  std::vector<char> key = tangentKey();
  const char* f = reinterpret_cast<const char*>(&velocityFactor);
  key.insert(key.end(), f, f + sizeof velocityFactor);
  if (key != jacobianKey_) {
    jacobianKey_ = key;
    for (size_t i = 0; i < links_.size(); ++i) {
      std::array<double, 9>& J = jacobian_[i];
      J.fill(0.0);
      if (!(trial_[i].normalForce > 0.0)) continue;  // no force here: none nearby on this side
      const ShockLink& l = links_[i];
      const double scale = std::max({std::sqrt(dot(d_[i], d_[i])), l.law.dist1 + l.law.dist2, 1e-3 * length_});
      const double h = 1e-8 * std::max(scale, 1e-300);
      // J[r][c] = d(force on node 2)_r / d(d)_c along u, with w moving by velocityFactor.
      for (int c = 0; c < 3; ++c) {
        Vec3 dp = d_[i], dm = d_[i], wp = w_[i], wm = w_[i];
        dp[c] += h, dm[c] -= h;
        wp[c] += velocityFactor * h, wm[c] -= velocityFactor * h;
        const Vec3 fp = force(i, dp, wp), fm = force(i, dm, wm);
        for (int r = 0; r < 3; ++r) J[3 * r + c] = (fp[r] - fm[r]) / (2 * h);
      }
    }
  }
  std::vector<MatrixEntry> entries;
  for (size_t i = 0; i < links_.size(); ++i) {
    const std::array<double, 9>& J = jacobian_[i];
    // Residual R_a = -s_a F2 with s = -1 on node 1, +1 on node 2; d moves by s_b du_b.
    for (int a = 0; a < 2; ++a)
      for (int r = 0; r < 3; ++r) {
        const GO row = dofs_[i][3 * a + r];
        if (row < 0 || map_->getLocalElement(row) == Teuchos::OrdinalTraits<LO>::invalid()) continue;
        for (int b = 0; b < 2; ++b)
          for (int c = 0; c < 3; ++c) {
            const GO col = dofs_[i][3 * b + c];
            if (col < 0 || J[3 * r + c] == 0.0) continue;
            entries.push_back({row, col, (a == b ? -1.0 : 1.0) * J[3 * r + c]});
          }
      }
  }
  return entries;
}

// The dashpots' dissipation is the work of the force's damping part (the force less the
// law's force without dampers, at the same state) over the step by the trapezoidal rule: the
// work the scheme itself applies (average acceleration: the mean of the step's end forces
// over the displacement), so the energy balance keeps only the error of the spring at a kink.
void DirectLinks::commit() {
  if (!pending_) return;
  for (size_t i = 0; i < links_.size(); ++i) {
    ShockLink& l = links_[i];
    l.last = evaluateShock(lawOfStep(i), d_[i], w_[i], dt_, l.state, true);
    recordKinematics(i, d_[i], w_[i]);
    ShockLawParameters elastic = l.law;
    elastic.normalDamping = elastic.tangentialDamping = 0.0;
    ShockLawState s = l.state;
    const Vec3 fe = evaluateShock(elastic, d_[i], w_[i], 0.0, s, false).forceOnNode2;
    const Vec3 fd{l.last.forceOnNode2[0] - fe[0], l.last.forceOnNode2[1] - fe[1],
                  l.last.forceOnNode2[2] - fe[2]};
    const Vec3 step{d_[i][0] - dPrev_[i][0], d_[i][1] - dPrev_[i][1], d_[i][2] - dPrev_[i][2]};
    // The elastic law's tangential force (stick spring or friction), its work the same way.
    const Vec3 m = shockGeometry(l.law, d_[i]).normal;
    const Vec3 ft{fe[0] - dot(fe, m) * m[0], fe[1] - dot(fe, m) * m[1], fe[2] - dot(fe, m) * m[2]};
    if (dt_ > 0.0) {
      dissipated_ -= 0.5 * (dot(fd, step) + dot(fdPrev_[i], step));
      if (l.law.tangential()) addTangentialWork(i, -0.5 * (dot(ft, step) + dot(ftPrev_[i], step)));
    }
    ftPrev_[i] = ft;
    fdPrev_[i] = fd;
    dPrev_[i] = d_[i];
  }
  pending_ = false;
}

void DirectLinks::archive(StateArchive& a) const {
  archiveLinks(a);
  std::vector<double> x;
  for (size_t i = 0; i < links_.size(); ++i)
    for (int c = 0; c < 3; ++c) x.push_back(dPrev_[i][c]), x.push_back(fdPrev_[i][c]), x.push_back(ftPrev_[i][c]);
  a.putVector("links/direct", x);
  std::vector<double> j;
  for (const auto& J : jacobian_) j.insert(j.end(), J.begin(), J.end());
  a.putVector("links/jacobian", j);
  a.putVector("links/jacobianKey", jacobianKey_);
  a.putInt("links/step", step_);
  a.putInt("links/dashpotDrops", dashpotDrops_);
}

void DirectLinks::restore(const StateArchive& a) {
  restoreLinks(a);
  const std::vector<double> x = a.getVector<double>("links/direct", 9 * links_.size());
  for (size_t i = 0; i < links_.size(); ++i)
    for (int c = 0; c < 3; ++c)
      dPrev_[i][c] = x[9 * i + 3 * c], fdPrev_[i][c] = x[9 * i + 3 * c + 1], ftPrev_[i][c] = x[9 * i + 3 * c + 2];
  const std::vector<double> j = a.getVector<double>("links/jacobian", 9 * links_.size());
  for (size_t i = 0; i < links_.size(); ++i) std::copy(j.begin() + 9 * i, j.begin() + 9 * i + 9, jacobian_[i].begin());
  jacobianKey_ = a.getVector<char>("links/jacobianKey");
  step_ = a.getInt("links/step");
  dashpotDrops_ = a.getInt("links/dashpotDrops");
  for (size_t i = 0; i < links_.size(); ++i) trial_[i] = links_[i].last;  // as after a commit
  pending_ = false;
}

}  // namespace choc
