// External loads of the direct transient: groups of nodal forces (on node sets) and pressures
// (on side sets, integrated with the faces' shape functions), each at full value from t = 0 or
// ramped linearly from zero at t = 0 to full at its ramp time, then constant. Pressures on the
// reference faces are constant vectors (dead loads); follower pressures (FollowerPressure.hpp)
// depend on the state: the model's nonlinear force computes them, and Loads keeps them for
// their work.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactFaces.hpp"
#include "core/TpetraTypes.hpp"
#include "core/Vec3.hpp"
#include "physics/FollowerPressure.hpp"

namespace choc {

// The ramp: 1 when rampTime is 0, else min(max(t, 0) / rampTime, 1).
double rampFactor(double rampTime, double t);

struct LoadGroup {
  std::string name;
  RCP<Vector> force;        // the full value
  double rampTime = 0.0;    // 0: full from t = 0
  // The fraction of the full value applied at time t.
  double factor(double t) const;
};

class Loads {
 public:
  // A group with the ramp time of an earlier one is summed into it (one vector per ramp).
  void add(LoadGroup g);
  void addFollower(std::shared_ptr<const StateLoad> f) { followers_.push_back(std::move(f)); }
  bool empty() const { return groups_.empty() && followers_.empty(); }
  // Some group ramps: the loads depend on time.
  bool ramped() const {
    for (const LoadGroup& g : groups_)
      if (g.rampTime > 0.0) return true;
    for (const auto& f : followers_)
      if (f->rampTime() > 0.0) return true;
    return false;
  }
  const std::vector<LoadGroup>& groups() const { return groups_; }
  const std::vector<std::shared_ptr<const StateLoad>>& followers() const { return followers_; }
  // out -= f(t).
  void subtractFrom(double t, Vector& out) const;

 private:
  std::vector<LoadGroup> groups_;
  std::vector<std::shared_ptr<const StateLoad>> followers_;
};

// The loads' work from the start: for each group, the trapezoidal rule in time on its factor
// against F.du, which is exact for constant loads and for ramps that end on a step; for the
// follower pressures, 1/2 (f(u_n, t_n) + f(u_n+1, t_n+1)) . (u_n+1 - u_n).
// update() is called once per accepted step, in order; the first call sets the start. A
// checkpoint keeps the last u of the followers' rule (followerDisplacement), from which
// restoreFollowers recomputes its force.
class LoadWork {
 public:
  explicit LoadWork(const Loads* loads) : loads_(loads) {}
  double update(const Vector& u, double t);
  // For a checkpoint: the work, the last time and each group's last F.u.
  std::vector<double> state() const;
  void restore(const std::vector<double>& s);
  size_t stateSize() const { return 3 + (loads_ ? loads_->groups().size() : 0); }
  bool hasFollowers() const { return loads_ && !loads_->followers().empty(); }
  const Vector* followerDisplacement() const { return uPrev_.get(); }
  void restoreFollowers(const Vector& u);

 private:
  void followerForce(const Vector& u, double t, Vector& out) const;
  const Loads* loads_;
  bool started_ = false;
  double work_ = 0.0, time_ = 0.0;
  std::vector<double> projection_;
  RCP<Vector> uPrev_, fPrev_, f_;  // the followers' last u and force
};

// The consistent nodal forces of a uniform pressure p on faces (positive pushing against the
// outward normal, into the body): f_a = -p integral of N_a n dA, by node. Axisymmetric edges are
// rings (length element weighted by 2 pi r): the forces of the whole 360-degree body.
std::map<int, Point3> pressureForces(const std::vector<Face>& faces, double p, bool axisymmetric);
// The same for p(X) = value + gradient . X at the reference faces' points.
std::map<int, Point3> pressureForces(const std::vector<Face>& faces, const PressureField& p, bool axisymmetric);

}  // namespace choc
