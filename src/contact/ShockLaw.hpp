// The nonlinear two-node shock law of the modal transient (DEFI_OBSTACLE shapes).
// d = x2 - x1 is the relative position of node 2 with respect to node 1 (current
// coordinates), w = v2 - v1 their relative velocity. The normal force is
//   F = max(0, -Kn delta - Cn d(delta)/dt)  while delta <= 0  (never tensile),
// along the shape's normal; tangential stiffness Kt, damping Ct and Coulomb friction mu act
// in the contact plane while the link is closed, by one of two friction laws:
//   elastic-plastic: an elastic tangential spring (its extension advanced by the tangential
//     relative velocity times dt) returned onto the Coulomb cone |Ft| <= mu F when it exceeds
//     it (slip); the stick stiffness unloads over 2 mu F / Kt at each reversal of the slip.
//   velocity reversal (code_aster's DIS_CHOC, the reference decks): while sliding the force is
//     -mu F along the tangential velocity; the link sticks when that velocity reverses (or
//     falls below 1e-6 m/s), from the last slip force, Ft = Ft_slip - Kt (d_t - d_t,slip) -
//     Ct w_t, and slides again (along the velocity) as soon as |Ft| > mu F. A reversal whose
//     step still moved the old way slides on at once: the stick stiffness then hardly acts and
//     the law is close to rigid-plastic Coulomb.
// Shapes (gaps):
//   BI_PLAN_Y / BI_PLAN_Z: two planes normal to e2 / e3: delta = |d.e| - DIST_1 - DIST_2
//   BI_CERCLE: two circles in the plane orthogonal to e1: delta = r - DIST_1 - DIST_2
//   BI_CERC_INT: inner circle (radius DIST_1) in an outer one (DIST_2):
//                delta = (DIST_2 - DIST_1) - r, the link pulls the nodes together.
//   PLAN_Y / PLAN_Z: one plane (a unilateral stop) whose outward normal is e2 / e3: node 1
//                stays on its +e side, delta = (x1 - x2).e - DIST_1 - DIST_2 (with one node:
//                x2 is the obstacle's origin, by default node 1's initial position, so
//                delta = u1.e - DIST_1 - DIST_2).
// With one node (a fixed obstacle), node 2 is the obstacle at its origin ('Obstacle Origin',
// ORIG_OBST; by default node 1's initial position).
// Normal law "rigid": no penetration at all. The link is then a unilateral constraint
// enforced by the integrator with a forward-increment Lagrange multiplier (the force at t_n is
// chosen so that the gap at t_{n+1} is closed, never tensile): see ModalLinks::project().
#pragma once
#include <string>
#include <vector>

#include "contact/ObstacleFrame.hpp"

namespace choc {

enum class ObstacleShape { BiPlanY, BiPlanZ, BiCercle, BiCercInt, PlanY, PlanZ };
enum class FrictionLaw { ElasticPlastic, VelocityReversal };

ObstacleShape parseObstacleShape(const std::string& name);  // std::invalid_argument if unknown
const std::vector<std::string>& obstacleShapeNames();

struct ShockLawParameters {
  ObstacleShape shape = ObstacleShape::BiPlanZ;
  bool rigid = false;  // normal law: penalty (false) or rigid constraint (true)
  ObstacleFrame frame{};
  double dist1 = 0.0, dist2 = 0.0;
  double normalStiffness = 0.0, normalDamping = 0.0;
  double tangentialStiffness = 0.0, tangentialDamping = 0.0, friction = 0.0;
  FrictionLaw frictionLaw = FrictionLaw::ElasticPlastic;
  bool tangential() const { return tangentialStiffness > 0 || tangentialDamping > 0 || friction > 0; }
};

// State carried between steps: elastic tangential displacement while closed (elastic-plastic);
// the last slip's force, relative position and the last tangential velocity (velocity
// reversal).
struct ShockLawState {
  Vec3 tangentialSpring{0.0, 0.0, 0.0};
  bool closed = false;
  bool sliding = false;
  Vec3 slipForce{0.0, 0.0, 0.0}, slipPosition{0.0, 0.0, 0.0}, tangentialVelocity{0.0, 0.0, 0.0};
};

struct ShockResponse {
  Vec3 forceOnNode2{0.0, 0.0, 0.0};  // node 1 receives the opposite
  double gap = 0.0;                  // delta
  double normalForce = 0.0;          // F >= 0
  double tangentialForce = 0.0;      // |Ft|
  bool closed = false;               // delta <= 0
  bool sliding = false;
  double springEnergy = 0.0;         // 1/2 Kn delta^2 + the tangential spring's, while closed
  double tangentialEnergy = 0.0;     // the tangential spring's part of springEnergy
  Vec3 tangentialForceVector{0.0, 0.0, 0.0};  // on node 2
  double slipSpeed = 0.0;            // |w_t| while closed
};

// Gap delta and outward unit normal m (the direction along which a positive force pushes
// node 2; d(delta) = m . d(d)) of the shape at relative position d.
struct ShockGeometry {
  double gap = 0.0;
  Vec3 normal{0.0, 0.0, 0.0};
};
ShockGeometry shockGeometry(const ShockLawParameters& p, const Vec3& d);

// Evaluates the law at relative position d and velocity w. `dt` advances the tangential
// spring (w_t += dt * tangential velocity); `state` is updated when `commit` is true.
ShockResponse evaluateShock(const ShockLawParameters& p, const Vec3& d, const Vec3& w, double dt,
                            ShockLawState& state, bool commit);

}  // namespace choc
