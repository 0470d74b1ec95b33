// One rigid body: its mass properties, its state (centre of mass, its velocity, attitude and
// spatial angular momentum about the centre), where its material points are and how fast they
// move, and the velocity-Verlet step of central differences (a kick by the force and torque
// on it, a drift: the centre moved, the attitude turned by the splitting of RotationStep.hpp).
// Every rank holds the whole body; the forces on its nodes are summed over the ranks by the
// caller (docs/theory/rigid-bodies.md).
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "rigid/MassProperties.hpp"
#include "rigid/RotationStep.hpp"

namespace choc {

// A body's held motion: the components `translation` of its centre's velocity kept at
// `velocity` [m/s], and with `rotation` its angular velocity kept at 0 (a guided striker, a
// punch driven at a constant speed).
struct RigidHold {
  std::array<bool, 3> translation{};
  bool rotation = false;
  Vec3 velocity{};
  bool any() const { return translation[0] || translation[1] || translation[2] || rotation; }
};

class RigidBody {
 public:
  RigidBody(std::string name, const MassProperties& properties);

  const std::string& name() const { return name_; }
  double mass() const { return p_.mass; }
  const Vec3& principalMoments() const { return p_.moments; }

  // The material point at reference position X: where it is, its displacement and velocity.
  Vec3 position(const Vec3& X) const;
  Vec3 displacement(const Vec3& X) const;
  Vec3 velocity(const Vec3& X) const;

  // The initial motion: the centre's velocity and the spatial angular velocity.
  void setMotion(const Vec3& velocity, const Vec3& angularVelocity);

  // Velocity Verlet: kick(F, T, h/2), drift(h), the forces at the new positions, kick(F, T, h/2).
  // F the resultant force on the body, T its moment about the current centre of mass. A held
  // body's kick ends on its held motion: the hold's impulse over the kick (divided by h, the
  // reaction) and its work (the impulse times the held velocity) are kept.
  void kick(const Vec3& force, const Vec3& torque, double h);
  void setHold(const RigidHold& hold);
  const RigidHold& hold() const { return hold_; }
  // The force and moment the hold applied over the last kick (0 without a hold), and its work
  // since the start [J].
  const Vec3& reactionForce() const { return reactionForce_; }
  const Vec3& reactionMoment() const { return reactionMoment_; }
  double holdWork() const { return holdWork_; }
  void drift(double h);
  // alpha = I^-1 (T - w x pi), the angular acceleration under the moment T about the centre.
  Vec3 angularAcceleration(const Vec3& torque) const;
  // The body-frame (principal) coordinates of the material point X: x = centre() + attitude() xi.
  Vec3 bodyCoordinates(const Vec3& X) const;
  // The moment about the centre of a force f at the material point X.
  Vec3 momentOf(const Vec3& X, const Vec3& force) const;

  const Vec3& centre() const { return centre_; }
  const Vec3& centreVelocity() const { return velocity_; }
  const Matrix33& attitude() const { return rotation_.R; }  // principal frame to space
  // The rotation since the start (space to space), as a rotation vector.
  Vec3 rotationVector() const;
  Vec3 angularVelocity() const;
  double kineticEnergy() const;
  Vec3 momentum() const;
  // About the origin: x_c x m V + pi.
  Vec3 angularMomentum() const;

  // The state for a checkpoint (25 numbers: the motion's 18, the hold's work and reaction), and
  // back (bit for bit).
  std::vector<double> state() const;
  void restore(const std::vector<double>& s);

 private:
  std::string name_;
  MassProperties p_;
  Vec3 centre_{}, velocity_{};
  RotationState rotation_;
  RigidHold hold_;
  Vec3 reactionForce_{}, reactionMoment_{};
  double holdWork_ = 0.0;
  // The held components set; returns the impulse and angular impulse that took.
  std::pair<Vec3, Vec3> enforceHold();
};

}  // namespace choc
