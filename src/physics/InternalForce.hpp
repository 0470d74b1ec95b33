// The structural model's internal force and its tangent: what the operator asks the elements
// for, and all it asks (the mass and damping, the loads, contact, links and the linear solver
// are the operator's other parts).
//
//   f_int(u)            internalForce(u, out)
//   K_T(u) = df_int/du  tangent(u): one matrix object on one graph for the whole run, its
//                       values refreshed in place when the state changes; tangentVersion()
//                       changes with them, and the operator's factorisation key includes it,
//                       so a stale factorisation of an old tangent cannot be reused.
//
// How a tangent that changes every Newton iteration flows: the integrator asks the operator
// for a correction at u; the operator calls tangent(u) (a nonlinear model assembles K_T(u)
// into its fixed graph and bumps its version), compares the version in its key, refills the
// effective matrix W = ca M + cv C + cd K_T (+ contact and links) and refactors or
// re-preconditions. A linear model returns K with a constant version: W is factored once per
// (coefficients, contact status) as before.
//
// Material state (per integration point) follows the steps (restart/SteppedState.hpp): each
// internalForce is a trial at its u, commit() when a step is accepted, revert() when it is cut or
// fails, archive()/restore() in checkpoints. The linear model has none.
//
// Rayleigh damping C = aK K0 + aM M uses the reference stiffness K0 (dampingStiffness; the
// tangent at u = 0), which for a linear model is K itself.
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/ElementValidity.hpp"
#include "restart/SteppedState.hpp"

namespace choc {

class InternalForce : public SteppedState {
 public:
  virtual ~InternalForce() = default;
  virtual RCP<const Map> map() const = 0;
  // out = f_int(u): a trial at u (the material points' new states kept as the trial).
  virtual void internalForce(const Vector& u, Vector& out) = 0;
  // K_T(u), on the same graph every call (see above).
  virtual RCP<const CrsMatrix> tangent(const Vector& u) = 0;
  virtual long long tangentVersion() const = 0;
  // out = K0 x, the stiffness of Rayleigh damping.
  virtual void applyDampingStiffness(const Vector& x, Vector& out) const = 0;
  // The time of the states the next internalForce and tangent calls are at: the ramps of the
  // state-dependent loads a nonlinear model carries (FollowerPressure). The operator sets it
  // with each residual, so a correction's tangent is at its residual's time.
  virtual void setTime(double /*t*/) {}
  // Is f_int affine in u (one tangent for the whole run)?
  virtual bool linear() const = 0;
  // The stored elastic energy at u, given f_int(u) when the caller holds it (else null).
  virtual double strainEnergy(const Vector& u, const Vector* internalForceAtU) const = 0;
  // || |K| |u| ||: the size of the terms whose sum is f_int(u), for the round-off floor of
  // Newton's residual test (0 when not known).
  virtual double termsNorm(const Vector& /*u*/) const { return 0.0; }
  // An upper bound of the largest eigenvalue of the state-dependent elements at u against their
  // lumped mass (the element bound, fem/ElementFrequencyBound.hpp), for an explicit run's
  // critical step on the deformed mesh; 0 when nothing depends on the state. Collective.
  virtual double stateEigenvalueBound(const Vector& /*u*/) const { return 0.0; }
  // Element variables for the results file: their names (none by default), the mesh blocks
  // that carry them (one flag per block), and their values at u, values[v][e] for every element
  // e of the mesh in global order, this rank's elements filled and the others 0 (the caller
  // sums over the ranks). Collective.
  virtual std::vector<std::string> elementFieldNames() const { return {}; }
  virtual std::vector<char> elementFieldBlocks() const { return {}; }
  virtual void elementFields(const Vector& /*u*/, std::vector<std::vector<double>>& /*values*/) const {}
  // Explicit runs stream the products of a symmetric model from half its entries.
  virtual void preferSymmetricProducts() {}
  // The one-point elements' hourglass energy at u (a part of the strain energy) [J], all ranks.
  // Collective.
  virtual double hourglassEnergy(const Vector& /*u*/) const { return 0.0; }
  // Whether the elements at u are still in the model's domain (ElementValidity.hpp): collective.
  virtual ElementValidity validity(const Vector& /*u*/) const { return {}; }
  // The work dissipated inside the material since the start (plastic work) [J], all ranks.
  virtual double dissipatedWork() const { return 0.0; }
  // Whether the force carries a history whose update has kinks in u (a plastic return map:
  // elastic or plastic at each point), where a full Newton correction can overshoot.
  virtual bool hasReturnMap() const { return false; }
};

}  // namespace choc
