// Penalty contact (PENALISATION): a spring of stiffness E_N per slave node, active when the
// node penetrates. A node enters when it penetrates by more than the gap tolerance and leaves
// when its gap exceeds it, so that a node touching at a gap of round-off size neither switches
// at every Newton solve nor depends on the sign of round-off (the frame the scene is drawn
// in); the spring's force in that band is at most E_N times the tolerance (0.01 N at the
// defaults).
#include "contact/ContactMethod.hpp"

namespace choc {

namespace {

class PenaltyContact : public ContactMethod {
 public:
  PenaltyContact(double k, double gapTol) : k_(k), gapTol_(gapTol) {}
  std::string name() const override { return "Penalty"; }
  bool hasMultipliers() const override { return false; }
  double force(double gap, double, bool active) const override { return active ? -k_ * gap : 0.0; }
  double stiffness() const override { return k_; }
  bool isActive(double gap, double, bool wasActive) const override {
    return wasActive ? gap < gapTol_ : gap < -gapTol_;
  }
  double energy(double gap, double, bool active) const override {
    return active ? 0.5 * k_ * gap * gap : 0.0;
  }

 private:
  double k_, gapTol_;
};

}  // namespace

std::unique_ptr<ContactMethod> makePenaltyContact(double penaltyStiffness, double gapTolerance) {
  return std::make_unique<PenaltyContact>(penaltyStiffness, gapTolerance);
}

}  // namespace choc
