// The rotation of a rigid body over one time step, from its spatial angular momentum about its
// centre of mass (docs/theory/rigid-bodies.md):
//   - explicit (central differences): the free rotation split into three rotations about the
//     principal axes, each exact (Dullweber, Leimkuhler and McLachlan 1997, symmetric: second
//     order); the angular momentum is conserved to round-off, the energy oscillates by O(h^2)
//     without drift; torques are applied as kicks of the momentum around it;
//   - implicit (Newmark, HHT): the energy-momentum midpoint rule (Simo and Wong 1991), an
//     incremental rotation theta in the body frame solved by Newton: with no torque the energy
//     and the angular momentum are conserved to the Newton tolerance, for any step.
// The body frame is the principal frame: R takes a body-frame vector to space, and the
// inertia about the centre is R diag(J) R^T.
#pragma once
#include <string>

#include "rigid/Rotation.hpp"

namespace choc {

struct RotationState {
  Matrix33 R = unitMatrix33();  // body (principal) frame to space
  Vec3 momentum{};       // spatial angular momentum about the centre of mass, pi = R J R^T w
};

// The spatial angular velocity w = R J^-1 R^T pi and the kinetic energy of rotation
// (1/2) pi . w.
Vec3 angularVelocity(const Vec3& J, const RotationState& s);
double rotationalEnergy(const Vec3& J, const RotationState& s);
// The state of a body turning at the spatial angular velocity w in attitude R.
RotationState stateFromAngularVelocity(const Vec3& J, const Matrix33& R, const Vec3& w);

// Explicit: the free rotation over h at constant pi (principal moments J > 0).
void rotateFreelyBySplitting(const Vec3& J, double h, RotationState& s);

// Implicit: R_{n+1} = R_n exp(theta^) with the momentum given at both ends (pi_{n+1} = pi_n
// free; pi_n + h times the step's torque otherwise), theta solving
//   theta = (h/2) J^-1 (R_n^T pi_n + exp(-theta^) R_n^T pi_{n+1})
// by Newton from theta = h J^-1 R_n^T pi_n, until the correction is within `tolerance` of
// |theta| (and of 1e-300 absolutely). Not converged: `message` says why and s is unchanged.
struct MidpointRotation {
  bool converged = false;
  int iterations = 0;
  Vec3 theta{};
  std::string message;
};
MidpointRotation rotateByMidpoint(const Vec3& J, double h, const Vec3& nextMomentum, RotationState& s,
                                  double tolerance = 1e-14, int maxIterations = 25);
// The midpoint rule's residual g(theta) and its tangent dg/dtheta (for the finite-difference
// check of the tangent).
Vec3 midpointResidual(const Vec3& J, double h, const Vec3& bodyMomentum, const Vec3& nextBodyMomentum,
                      const Vec3& theta);
Matrix33 midpointTangent(const Vec3& J, double h, const Vec3& nextBodyMomentum, const Vec3& theta);

}  // namespace choc
