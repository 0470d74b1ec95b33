// How a contact constraint is enforced, per slave node s with gap g_s(u) = g0 + B_s u and
// (for the multiplier methods) a pressure unknown lambda_s [N]. The manager applies the
// normal force f_s (compression positive) as -f_s B_s^T in the residual, adds k_s B_s^T B_s
// to the effective matrix of an active node, and re-evaluates the status after each Newton
// solve with the method's complementarity test.
#pragma once
#include <memory>
#include <string>

namespace choc {

class ContactMethod {
 public:
  virtual ~ContactMethod() = default;
  virtual std::string name() const = 0;
  // Pressure unknowns at the slave nodes (saddle-point system)?
  virtual bool hasMultipliers() const = 0;
  // Normal force of a node with the status frozen [N].
  virtual double force(double gap, double lambda, bool active) const = 0;
  // k_s: -d force / d gap for an active node [N/m].
  virtual double stiffness() const = 0;
  // Complementarity test: the node's status after a converged Newton solve.
  virtual bool isActive(double gap, double lambda, bool wasActive) const = 0;
  // Energy stored in the constraint [J] (penalty spring), 0 otherwise.
  virtual double energy(double /*gap*/, double /*lambda*/, bool /*active*/) const { return 0.0; }
};

// CONTRAINTE: lambda >= 0, g >= 0, lambda g = 0 with an active set; an active node keeps
// g = 0 exactly (to solver tolerance), a node enters when g < -gapTolerance and leaves when
// lambda < 0.
std::unique_ptr<ContactMethod> makeLagrangeContact(double gapTolerance);
// PENALISATION: f = -E_N g for an active node, E_N [N/m] per slave node; a node enters when
// g < -gapTolerance and leaves when g >= gapTolerance.
std::unique_ptr<ContactMethod> makePenaltyContact(double penaltyStiffness, double gapTolerance);
// CONTINUE: augmented Lagrangian, f = lambda - c g for an active node with the constraint
// g = 0; active when lambda - c g > 0 (entering needs g < -gapTolerance).
std::unique_ptr<ContactMethod> makeAugmentedLagrangianContact(double coefficient,
                                                              double gapTolerance);

}  // namespace choc
