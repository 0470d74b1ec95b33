// Lagrange multipliers with an active set (CONTRAINTE).
#include "contact/ContactMethod.hpp"

namespace choc {

namespace {

class LagrangeContact : public ContactMethod {
 public:
  explicit LagrangeContact(double gapTol) : gapTol_(gapTol) {}
  std::string name() const override { return "Lagrange"; }
  bool hasMultipliers() const override { return true; }
  double force(double, double lambda, bool active) const override { return active ? lambda : 0.0; }
  double stiffness() const override { return 0.0; }
  bool isActive(double gap, double lambda, bool wasActive) const override {
    return wasActive ? lambda >= 0.0 : gap < -gapTol_;
  }

 private:
  double gapTol_;
};

}  // namespace

std::unique_ptr<ContactMethod> makeLagrangeContact(double gapTolerance) {
  return std::make_unique<LagrangeContact>(gapTolerance);
}

}  // namespace choc
