// Penalty contact (PENALISATION): a spring of stiffness E_N per slave node, active when the
// node penetrates.
#include "contact/ContactMethod.hpp"

namespace choc {

namespace {

class PenaltyContact : public ContactMethod {
 public:
  explicit PenaltyContact(double k) : k_(k) {}
  std::string name() const override { return "Penalty"; }
  bool hasMultipliers() const override { return false; }
  double force(double gap, double, bool active) const override { return active ? -k_ * gap : 0.0; }
  double stiffness() const override { return k_; }
  bool isActive(double gap, double, bool) const override { return gap < 0.0; }
  double energy(double gap, double, bool active) const override {
    return active ? 0.5 * k_ * gap * gap : 0.0;
  }

 private:
  double k_;
};

}  // namespace

std::unique_ptr<ContactMethod> makePenaltyContact(double penaltyStiffness) {
  return std::make_unique<PenaltyContact>(penaltyStiffness);
}

}  // namespace choc
