#include "rigid/RigidBody.hpp"

#include <stdexcept>
#include <utility>

namespace choc {

namespace {

Vec3 plus(const Vec3& a, const Vec3& b, double f = 1.0) { return {a[0] + f * b[0], a[1] + f * b[1], a[2] + f * b[2]}; }

}  // namespace

RigidBody::RigidBody(std::string name, const MassProperties& properties)
    : name_(std::move(name)), p_(properties), centre_(properties.centre) {
  if (!(p_.mass > 0.0)) throw std::invalid_argument("rigid body '" + name_ + "': no mass");
  for (double J : p_.moments)
    if (!(J > 0.0))
      throw std::invalid_argument("rigid body '" + name_ + "': a principal moment of inertia is not positive "
                                  "(its elements all on one line?)");
  rotation_.R = p_.axes;
}

// x = c + R A0^T (X - c0): the body-frame coordinates of X turned to the current attitude.
Vec3 RigidBody::position(const Vec3& X) const { return plus(centre_, rotation_.R * bodyCoordinates(X)); }

Vec3 RigidBody::displacement(const Vec3& X) const { return position(X) - X; }

Vec3 RigidBody::velocity(const Vec3& X) const {
  return plus(velocity_, cross(angularVelocity(), position(X) - centre_));
}

void RigidBody::setMotion(const Vec3& velocity, const Vec3& angularVelocity) {
  velocity_ = velocity;
  rotation_ = stateFromAngularVelocity(p_.moments, rotation_.R, angularVelocity);
}

void RigidBody::kick(const Vec3& force, const Vec3& torque, double h) {
  velocity_ = plus(velocity_, force, h / p_.mass);
  rotation_.momentum = plus(rotation_.momentum, torque, h);
  if (!hold_.any()) return;
  const auto [J, K] = enforceHold();
  reactionForce_ = {J[0] / h, J[1] / h, J[2] / h};
  reactionMoment_ = {K[0] / h, K[1] / h, K[2] / h};
  holdWork_ += dot(J, hold_.velocity);  // the held rotation's is 0 (w = 0)
}

void RigidBody::setHold(const RigidHold& hold) {
  hold_ = hold;
  enforceHold();
}

std::pair<Vec3, Vec3> RigidBody::enforceHold() {
  Vec3 J{}, K{};
  for (int c = 0; c < 3; ++c)
    if (hold_.translation[size_t(c)]) {
      J[size_t(c)] = p_.mass * (hold_.velocity[size_t(c)] - velocity_[size_t(c)]);
      velocity_[size_t(c)] = hold_.velocity[size_t(c)];
    }
  if (hold_.rotation) {
    K = {-rotation_.momentum[0], -rotation_.momentum[1], -rotation_.momentum[2]};
    rotation_.momentum = Vec3{};
  }
  return {J, K};
}

void RigidBody::drift(double h) {
  centre_ = plus(centre_, velocity_, h);
  rotateFreelyBySplitting(p_.moments, h, rotation_);
}

Vec3 RigidBody::angularAcceleration(const Vec3& torque) const {
  const Vec3 net = torque - cross(angularVelocity(), rotation_.momentum);
  const Vec3 body = transpose(rotation_.R) * net;
  return rotation_.R * Vec3{body[0] / p_.moments[0], body[1] / p_.moments[1], body[2] / p_.moments[2]};
}

Vec3 RigidBody::bodyCoordinates(const Vec3& X) const { return transpose(p_.axes) * (X - p_.centre); }

Vec3 RigidBody::momentOf(const Vec3& X, const Vec3& force) const { return cross(position(X) - centre_, force); }

Vec3 RigidBody::rotationVector() const { return vectorFromRotation(rotation_.R * transpose(p_.axes)); }

Vec3 RigidBody::angularVelocity() const { return choc::angularVelocity(p_.moments, rotation_); }

double RigidBody::kineticEnergy() const {
  return 0.5 * p_.mass * dot(velocity_, velocity_) + rotationalEnergy(p_.moments, rotation_);
}

Vec3 RigidBody::momentum() const { return {p_.mass * velocity_[0], p_.mass * velocity_[1], p_.mass * velocity_[2]}; }

Vec3 RigidBody::angularMomentum() const { return plus(cross(centre_, momentum()), rotation_.momentum); }

std::vector<double> RigidBody::state() const {
  std::vector<double> s(centre_.begin(), centre_.end());
  s.insert(s.end(), velocity_.begin(), velocity_.end());
  s.insert(s.end(), rotation_.R.begin(), rotation_.R.end());
  s.insert(s.end(), rotation_.momentum.begin(), rotation_.momentum.end());
  s.push_back(holdWork_);
  s.insert(s.end(), reactionForce_.begin(), reactionForce_.end());
  s.insert(s.end(), reactionMoment_.begin(), reactionMoment_.end());
  return s;
}

void RigidBody::restore(const std::vector<double>& s) {
  if (s.size() != 25) throw std::invalid_argument("rigid body '" + name_ + "': a checkpoint state of 25 numbers expected");
  for (int i = 0; i < 3; ++i) centre_[i] = s[i], velocity_[i] = s[3 + i], rotation_.momentum[i] = s[15 + i];
  holdWork_ = s[18];
  for (int i = 0; i < 3; ++i) reactionForce_[i] = s[19 + i], reactionMoment_[i] = s[22 + i];
  for (int k = 0; k < 9; ++k) rotation_.R[k] = s[6 + k];
}

}  // namespace choc
