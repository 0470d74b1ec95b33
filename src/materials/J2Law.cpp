// 'J2 plasticity': von Mises plasticity with isotropic hardening, linear or by a flow curve, and
// optional linear kinematic hardening in small strain (J2Plasticity.hpp), on either kinematics.
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "input/ParameterSpec.hpp"
#include "input/XmlInput.hpp"
#include "materials/J2Law.hpp"
#include "materials/J2Point.hpp"

namespace choc {

namespace {

// The 'Flow Curve' pairs into p.curve.
void parseFlowCurve(const LawInput& in, const std::string& curve, J2Parameters& p) {
  std::istringstream text(curve);
  std::string token;
  std::vector<double> numbers;
  while (text >> token) {
    double v = 0;
    if (!parseDecimal(token, v) || !std::isfinite(v))
      throwInput(in.file, in.path + "Flow Curve", curve, "'" + token + "' is not a number",
                 "give pairs 'plastic_strain stress [Pa]'");
    numbers.push_back(v);
  }
  if (numbers.empty() || numbers.size() % 2 != 0)
    throwInput(in.file, in.path + "Flow Curve", curve, "the curve has " + std::to_string(numbers.size()) + " numbers",
               "give pairs 'plastic_strain stress [Pa]', the first at plastic strain 0");
  for (size_t i = 0; i < numbers.size(); i += 2) {
    p.curve.strain.push_back(numbers[i]);
    p.curve.stress.push_back(numbers[i + 1]);
  }
}

class J2PlasticityLaw : public MaterialLaw {
 public:
  const char* name() const override { return "J2 plasticity"; }
  std::string description() const override {
    return "'J2 plasticity' (von Mises, isotropic hardening: linear or a flow curve; direct transients)";
  }
  bool smallStrain() const override { return true; }
  bool finiteStrain() const override { return true; }
  bool dissipative() const override { return true; }
  void declare(Teuchos::ParameterList& mat) const override {
    declareDouble(mat, "Yield Stress", 0.0,
                  "'J2 plasticity': the initial yield stress sigma_y [Pa] (required, > 0, with that model)",
                  Range::nonNegative());
    declareDouble(mat, "Hardening Modulus", 0.0,
                  "'J2 plasticity': the linear isotropic hardening H = d sigma_y / d alpha [Pa], alpha "
                  "the equivalent plastic strain (0: perfectly plastic)",
                  Range::nonNegative());
    declareDouble(mat, "Kinematic Hardening Modulus", 0.0,
                  "'J2 plasticity' and 'Johnson-Cook' on small-strain blocks: linear kinematic hardening "
                  "(Prager-Ziegler), the yield surface's centre moving with the flow, d beta = 2/3 H_k d eps_p "
                  "[Pa] (0: none; the Bauschinger effect of cyclic loading); refused on finite-strain blocks",
                  Range::nonNegative());
    declareString(mat, "Flow Curve", "",
                  "'J2 plasticity': the flow stress as a piecewise-linear curve 'alpha_0 sigma_0 alpha_1 "
                  "sigma_1 ...' of equivalent plastic strain [-] and stress [Pa] (alpha_0 = 0, alpha "
                  "increasing, sigma non-decreasing, constant beyond the last point), instead of 'Yield "
                  "Stress' and 'Hardening Modulus'");
  }
  std::vector<std::string> keysRead(const Teuchos::ParameterList&) const override {
    return {"Yield Stress", "Hardening Modulus", "Kinematic Hardening Modulus", "Flow Curve"};
  }
  void checkKeys(const LawInput& in) const override {
    const auto missing = [&](const std::string& key) { return in.keys.getEntry(key).isDefault(); };
    if (missing("Yield Stress") && missing("Flow Curve"))
      throwInput(in.file, in.path + "Yield Stress", "", "is missing: 'J2 plasticity' needs the initial yield stress",
                 "give 'Yield Stress' > 0 [Pa], or a 'Flow Curve'");
  }
  std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool finiteStrain) const override {
    J2Parameters p = j2Parameters(in, finiteStrain);
    const std::string curve = in.keys.get<std::string>("Flow Curve");
    if (curve.empty()) {
      if (!(p.yieldStress > 0))
        throwInput(in.file, in.path + "Yield Stress", format("%g", p.yieldStress),
                   "'J2 plasticity' needs the initial yield stress", "give 'Yield Stress' > 0 [Pa], or a 'Flow Curve'");
    } else {
      if (p.yieldStress > 0 || p.hardening > 0)
        throwInput(in.file, in.path + "Flow Curve", curve,
                   "a flow curve and 'Yield Stress'/'Hardening Modulus' are both given", "give one of them");
      parseFlowCurve(in, curve, p);
    }
    return j2LawPoint(in, p, finiteStrain);
  }
};

}  // namespace

J2Parameters j2Parameters(const LawInput& in, bool finiteStrain) {
  const Teuchos::ParameterList& k = in.keys;
  J2Parameters p = linearHardening(k.get<double>("Young's Modulus"), k.get<double>("Poisson's Ratio"),
                                   k.get<double>("Yield Stress"), k.get<double>("Hardening Modulus"));
  p.kinematicHardening = k.get<double>("Kinematic Hardening Modulus");
  if (finiteStrain && p.kinematicHardening > 0)
    throwInput(in.file, in.path + "Kinematic Hardening Modulus", format("%g", p.kinematicHardening),
               "kinematic hardening is small-strain only; block '" + in.block + "' has 'Strain' = 'finite'",
               "set the block's 'Strain' = 'small', or 'Kinematic Hardening Modulus' = 0");
  return p;
}

std::shared_ptr<const MaterialPoint> j2LawPoint(const LawInput& in, const J2Parameters& p, bool finiteStrain) {
  try {
    return j2Point(std::make_shared<const J2Plasticity>(p, finiteStrain));
  } catch (const std::invalid_argument& e) {
    throwInput(in.file, in.path.substr(0, in.path.size() - 1), "", e.what());
  }
}

const MaterialLaw& j2PlasticityLaw() {
  static const J2PlasticityLaw law;
  return law;
}

}  // namespace choc
