// The "continuous" formulation (CONTINUE): pressure unknowns at the slave nodes and an
// augmented Lagrangian f = lambda - c g; the status, frozen during each Newton solve, is
// re-evaluated after it from the sign of the augmented pressure (fixed point).
#include "contact/ContactMethod.hpp"

namespace choc {

namespace {

class AugmentedLagrangianContact : public ContactMethod {
 public:
  AugmentedLagrangianContact(double c, double gapTol) : c_(c), gapTol_(gapTol) {}
  std::string name() const override { return "Continuous (augmented Lagrangian)"; }
  bool hasMultipliers() const override { return true; }
  double force(double gap, double lambda, bool active) const override {
    return active ? lambda - c_ * gap : 0.0;
  }
  double stiffness() const override { return c_; }
  bool isActive(double gap, double lambda, bool wasActive) const override {
    const double augmented = (wasActive ? lambda : 0.0) - c_ * gap;
    return augmented > (wasActive ? 0.0 : c_ * gapTol_);
  }

 private:
  double c_, gapTol_;
};

}  // namespace

std::unique_ptr<ContactMethod> makeAugmentedLagrangianContact(double coefficient,
                                                              double gapTolerance) {
  return std::make_unique<AugmentedLagrangianContact>(coefficient, gapTolerance);
}

}  // namespace choc
