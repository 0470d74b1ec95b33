// The interface a second-order integrator sees (STYLE: "the integrator sees an operator,
// never an element"): for  M a + C v + K u + f_c(u) = f_ext(t)  it gives
//   - the inertia M a and the weighted forces F(u, v, t) = C v + K u - f_ext(t);
//   - the constraint (contact) and link forces f_c(u, v) at the end of the step, which the
//     schemes do not weight (a constraint holds at t_{n+1}), with the residual of the
//     constraint equations when the operator carries extra unknowns (Lagrange multipliers);
//   - Newton corrections with the effective matrix W = c_a M + c_v C + c_d K (+ the
//     constraint block), which the operator may factor once per key (c_a, c_v, c_d, status);
//   - a fixed point on the constraint status (active set) after each converged Newton solve.
// Vectors live on map(); the operator keeps its own extra unknowns and their saved copies.
#pragma once
#include <string>

#include "core/TpetraTypes.hpp"
#include "fem/ElementValidity.hpp"
#include "restart/SteppedState.hpp"

namespace choc {

// W = ca M + cv C + cd K.
struct EffectiveCoefficients {
  double ca = 0.0, cv = 0.0, cd = 0.0;
  bool operator==(const EffectiveCoefficients& o) const {
    return ca == o.ca && cv == o.cv && cd == o.cd;
  }
};

struct CorrectionStatus {
  bool ok = false;
  int iterations = 0;        // Krylov iterations (0: direct)
  bool refactored = false;   // the effective matrix was (re)factored for this solve
  std::string message;       // why it failed
};

struct ConstraintUpdate {
  bool changed = false;      // some status changed (on any rank)
  int active = 0;            // active constraints after the update
  std::string summary;       // e.g. "3 -> 4 active"
};

class SecondOrderOperator : public SteppedState {
 public:
  virtual ~SecondOrderOperator() = default;
  virtual RCP<const Map> map() const = 0;

  // out = M a
  virtual void applyMass(const Vector& a, Vector& out) = 0;
  // out = C v + K u - f_ext(t)
  virtual void applyForces(const Vector& u, const Vector& v, double t, Vector& out) = 0;
  // out += f_c(u, v) with the current extra unknowns and frozen status (v: the velocity that
  // goes with u, for dashpots); returns the norm of the constraint equations' residual in
  // force units (0 when there are none).
  virtual double addConstraintForces(const Vector& u, const Vector& v, Vector& out) = 0;
  // Solves [W + constraint block] (du, dz) = -(r, r_z) and updates the operator's own extra
  // unknowns z by dz; du is returned. r is the full residual (with constraint forces). The
  // velocity follows u with dv/du = cv / cd.
  virtual CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u,
                                           const Vector& r, Vector& du) = 0;
  // The next solveCorrection may stop an iterative linear solve once its relative residual is
  // at most `relative` (inexact Newton; see NewtonSettings::adaptiveLinearTolerance). By
  // default ignored: the operator solves exactly or to its own tolerance.
  virtual void relaxNextCorrection(double /*relative*/) {}
  // Initial acceleration from equilibrium: solves M a = -r (r = F(u0, v0, t0) + f_c(u0)); by
  // default with W = M (plus the constraint block). An operator whose M is singular (massless
  // DOFs) overrides it.
  virtual CorrectionStatus solveInitialAcceleration(const Vector& u, const Vector& r, Vector& a) {
    EffectiveCoefficients mass;
    mass.ca = 1.0;
    return solveCorrection(mass, u, r, a);
  }
  // Before the step of length dt to time t from the accepted state u (and before the initial
  // state, with t the start time and dt = 0): constraints that follow the motion are updated.
  virtual void beginStep(const Vector& /*u*/, double /*t*/, double /*dt*/) {}
  // The constraints' state for a failure message, e.g. "pair 'slide': 28 of 28 nodes in
  // contact" ("" when there are none).
  virtual std::string constraintState() const { return ""; }
  // || |K| |u| ||: the size of the terms whose sum is the elastic force at u, for the
  // round-off floor of the residual (0 when not known).
  virtual double elasticTermsNorm(const Vector& /*u*/) const { return 0.0; }
  // Whether applyForces depends on t (time-dependent loads). When not, a step's forces at its
  // converged u are the next step's F_n without recomputing them.
  virtual bool forcesVaryInTime() const { return true; }
  // Whether a converged state u is in the model's domain (no element inverted at a corner or a
  // point, small strain within its bound: ElementValidity.hpp); collective.
  virtual ElementValidity validity(const Vector& /*u*/) const { return {}; }
  // The motion up to u is accepted (before commit): state that accumulates over accepted steps.
  virtual void commitMotion(const Vector& /*u*/) {}
  // An accepted implicit step's velocity and acceleration corrected by the constraints' impact
  // treatment (the contact velocity update): whether a changed, and whether the forces F(u, v)
  // did (v changed where damping or links act on it).
  struct CorrectedFields {
    bool forces = false, acceleration = false;
  };
  virtual CorrectedFields correctVelocity(Vector& /*v*/, Vector& /*a*/) { return {}; }
  // Is R(u) affine in u while the constraint status is frozen (linear elasticity, contact
  // without friction, no shock links)? Then one exact correction solves an active-set pass.
  // false (the default) is always safe.
  virtual bool linearWithinPass() const { return false; }
  // Whether the residual has kinks in u (plastic return maps: elastic or plastic at each point),
  // where a full Newton correction can overshoot: Newton then searches along its corrections
  // and updates the constraint status after converged solves (NewtonSettings, 'auto').
  virtual bool residualHasKinks() const { return false; }
  // The extra unknowns' last correction dz scaled by `factor` (the line search shortened du).
  virtual void scaleLastCorrection(double /*factor*/) {}
  // Re-evaluates the constraint status at u (after a converged Newton solve).
  virtual ConstraintUpdate updateConstraints(const Vector& u) = 0;
  // Initial status from u (before the first step).
  virtual void initializeConstraints(const Vector& /*u*/) {}
  // commit(), revert(), archive() and restore() (restart/SteppedState.hpp): the material
  // points', the constraints' extra unknowns and statuses, and the links' state of the last
  // accepted step.
};

}  // namespace choc
