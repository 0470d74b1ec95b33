// What explicit central differences need from an operator beyond the second-order interface
// (timeint/SecondOrderOperator.hpp), which the implicit schemes see without these hooks:
//   - exactly enforced contact by forward increments (Lagrange multipliers; then
//     addConstraintForces and updateConstraints leave contact out): given the predicted next
//     position uStar (the free motion from u over the sub-step h) and the factor h2 by which
//     an acceleration moves it, addExplicitContact adds to a the contact accelerations
//     M^-1 B^T lambda that leave no gap of uStar + h2 M^-1 B^T lambda negative (and the
//     friction forces' accelerations, which stop the tangential motion up to mu lambda), and
//     subtracts the contact forces B^T lambda from the residual r (rigid bodies gather them);
//   - keepProducts: whether applyForces keeps its products (K u, K v, M v) for the energies of
//     that state (on by default); the explicit loop turns it off for the sub-steps no output
//     follows, whose copies would cost a tenth of such a sub-step.
#pragma once
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

class ExplicitOperator : public SecondOrderOperator {
 public:
  virtual bool hasExplicitContact() const { return false; }
  virtual void addExplicitContact(const Vector& /*u*/, const Vector& /*uStar*/, const Vector& /*inverseMass*/,
                                  double /*h*/, double /*h2*/, Vector& /*a*/, Vector& /*r*/) {}
  virtual void keepProducts(bool /*on*/) {}
};

}  // namespace choc
