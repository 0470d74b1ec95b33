#include "contact/ShockLaw.hpp"

#include <cmath>
#include <stdexcept>

namespace choc {

const std::vector<std::string>& obstacleShapeNames() {
  static const std::vector<std::string> names = {"BI_PLAN_Y", "BI_PLAN_Z", "BI_CERCLE",
                                                 "BI_CERC_INT", "PLAN_Y", "PLAN_Z"};
  return names;
}

ObstacleShape parseObstacleShape(const std::string& name) {
  if (name == "BI_PLAN_Y") return ObstacleShape::BiPlanY;
  if (name == "BI_PLAN_Z") return ObstacleShape::BiPlanZ;
  if (name == "BI_CERCLE") return ObstacleShape::BiCercle;
  if (name == "BI_CERC_INT") return ObstacleShape::BiCercInt;
  if (name == "PLAN_Y") return ObstacleShape::PlanY;
  if (name == "PLAN_Z") return ObstacleShape::PlanZ;
  throw std::invalid_argument("unknown obstacle shape '" + name + "'");
}

namespace {
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// Elastic-plastic: the spring extension advanced by w_t dt, returned onto the cone.
Vec3 returnMappedFriction(const ShockLawParameters& p, const ShockLawState& state, double dt,
                          const Vec3& m, const Vec3& wt, double normalForce, ShockLawState& next,
                          ShockResponse& r) {
  Vec3 spring = state.closed ? state.tangentialSpring : Vec3{0, 0, 0};
  spring = plus(spring, scaled(wt, dt));
  spring = minus(spring, scaled(m, dot(spring, m)));  // stays in the contact plane
  Vec3 ft = scaled(plus(scaled(spring, p.tangentialStiffness), scaled(wt, p.tangentialDamping)), -1.0);
  const double ftn = norm(ft);
  const double limit = p.friction * normalForce;
  if (p.friction > 0 && ftn > limit) {
    // Slip: the force sits on the Coulomb cone, the spring keeps the elastic part.
    ft = scaled(ft, limit / ftn);
    r.sliding = true;
    if (p.tangentialStiffness > 0)
      spring = scaled(plus(ft, scaled(wt, p.tangentialDamping)), -1.0 / p.tangentialStiffness);
  }
  r.tangentialEnergy = 0.5 * p.tangentialStiffness * dot(spring, spring);
  next.tangentialSpring = spring;
  return ft;
}

// Velocity reversal (code_aster's DIS_CHOC): see the header.
Vec3 reversalFriction(const ShockLawParameters& p, const ShockLawState& state, const Vec3& d,
                      const Vec3& m, const Vec3& wt, double normalForce, ShockLawState& next,
                      ShockResponse& r) {
  const double speed = norm(wt), limit = p.friction * normalForce;
  // Just closed: no slip recorded yet; the link slides if it moves.
  const bool wasSliding = state.closed ? state.sliding : true;
  const Vec3 slipForce = state.closed ? state.slipForce : Vec3{0, 0, 0};
  const Vec3 slipPosition = state.closed ? state.slipPosition : d;
  const Vec3 lastVelocity = state.closed ? state.tangentialVelocity : Vec3{0, 0, 0};
  const double kSpeed = 1e-6;  // m/s: below it a sliding link sticks
  Vec3 ft{0, 0, 0};
  if (wasSliding && dot(wt, lastVelocity) >= 0.0 && speed > kSpeed && p.friction > 0) {
    ft = scaled(wt, -limit / speed);
    next.sliding = true;
    next.slipForce = ft;
    next.slipPosition = d;
  } else {
    Vec3 moved = minus(d, slipPosition);
    moved = minus(moved, scaled(m, dot(moved, m)));  // in the contact plane
    ft = minus(slipForce, plus(scaled(moved, p.tangentialStiffness), scaled(wt, p.tangentialDamping)));
    next.sliding = false;
    next.slipForce = slipForce;
    next.slipPosition = slipPosition;
    if (p.friction > 0 && norm(ft) > limit) {
      ft = speed > 0 ? scaled(wt, -limit / speed) : Vec3{0, 0, 0};
      next.sliding = true;
      next.slipForce = ft;
      next.slipPosition = d;
    }
  }
  r.sliding = next.sliding;
  next.tangentialVelocity = wt;
  // The elastic part of a sticking link's force (its spring's energy, |Ft|^2 / 2 Kt).
  if (!next.sliding && p.tangentialStiffness > 0) {
    const Vec3 fe = minus(ft, scaled(wt, -p.tangentialDamping));
    r.tangentialEnergy = 0.5 * dot(fe, fe) / p.tangentialStiffness;
  }
  return ft;
}

}  // namespace

ShockGeometry shockGeometry(const ShockLawParameters& p, const Vec3& d) {
  ShockGeometry g;
  switch (p.shape) {
    case ObstacleShape::BiPlanY:
    case ObstacleShape::BiPlanZ: {
      const Vec3& e = p.shape == ObstacleShape::BiPlanY ? p.frame.e2 : p.frame.e3;
      const double s = dot(d, e);
      g.normal = scaled(e, s >= 0 ? 1.0 : -1.0);
      g.gap = std::abs(s) - p.dist1 - p.dist2;
      break;
    }
    case ObstacleShape::PlanY:
    case ObstacleShape::PlanZ: {
      // e is the obstacle's outward normal: node 1 stays on its +e side.
      const Vec3& e = p.shape == ObstacleShape::PlanY ? p.frame.e2 : p.frame.e3;
      g.normal = scaled(e, -1.0);
      g.gap = -dot(d, e) - p.dist1 - p.dist2;
      break;
    }
    case ObstacleShape::BiCercle:
    case ObstacleShape::BiCercInt: {
      const Vec3 dp = minus(d, scaled(p.frame.e1, dot(d, p.frame.e1)));
      const double rr = norm(dp);
      // At r = 0 the direction is undefined: take e2 (only reached if the nodes coincide).
      const Vec3 radial = rr > 0 ? scaled(dp, 1.0 / rr) : p.frame.e2;
      if (p.shape == ObstacleShape::BiCercle) {
        g.normal = radial;
        g.gap = rr - p.dist1 - p.dist2;
      } else {
        g.normal = scaled(radial, -1.0);  // the outer circle pulls node 2 back towards node 1
        g.gap = (p.dist2 - p.dist1) - rr;
      }
      break;
    }
  }
  return g;
}

ShockResponse evaluateShock(const ShockLawParameters& p, const Vec3& d, const Vec3& w, double dt,
                            ShockLawState& state, bool commit) {
  ShockResponse r;
  const ShockGeometry geo = shockGeometry(p, d);
  const Vec3& m = geo.normal;
  r.gap = geo.gap;
  const double gapRate = dot(w, m);  // d(delta)/dt for every shape
  r.closed = r.gap <= 0.0;
  ShockLawState next = state;
  if (!r.closed) {
    next.tangentialSpring = {0, 0, 0};
    next.closed = false;
    next.sliding = false;
    next.slipForce = {0, 0, 0};
  } else {
    r.normalForce = std::max(0.0, -p.normalStiffness * r.gap - p.normalDamping * gapRate);
    Vec3 force = scaled(m, r.normalForce);
    r.springEnergy = 0.5 * p.normalStiffness * r.gap * r.gap;
    if (p.tangential()) {
      const Vec3 wt = minus(w, scaled(m, gapRate));  // tangential relative velocity
      r.slipSpeed = norm(wt);
      Vec3 ft = p.frictionLaw == FrictionLaw::VelocityReversal
                    ? reversalFriction(p, state, d, m, wt, r.normalForce, next, r)
                    : returnMappedFriction(p, state, dt, m, wt, r.normalForce, next, r);
      r.tangentialForce = norm(ft);
      r.tangentialForceVector = ft;
      force = plus(force, ft);
      r.springEnergy += r.tangentialEnergy;
    }
    next.closed = true;
    r.forceOnNode2 = force;
  }
  if (commit) state = next;
  return r;
}

}  // namespace choc
