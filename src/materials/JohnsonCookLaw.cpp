// 'Johnson-Cook': J2 plasticity with the Johnson-Cook flow stress, its strain rate and adiabatic
// heating (FlowStress.hpp), and optionally Johnson and Cook's cumulative damage
// (JohnsonCookDamage.hpp), on either kinematics.
#include <algorithm>

#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Validation.hpp"
#include "materials/J2Law.hpp"

namespace choc {

namespace {

const std::vector<std::string>& flowKeys() {
  static const std::vector<std::string> k{"Johnson-Cook A",        "Johnson-Cook B",          "Johnson-Cook n",
                                          "Johnson-Cook C",        "Reference Strain Rate",   "Johnson-Cook m",
                                          "Reference Temperature", "Melting Temperature",     "Initial Temperature",
                                          "Specific Heat",         "Taylor-Quinney Coefficient"};
  return k;
}

const std::vector<std::string>& damageKeys() {
  static const std::vector<std::string> k{"Johnson-Cook D1", "Johnson-Cook D2", "Johnson-Cook D3", "Johnson-Cook D4",
                                          "Johnson-Cook D5"};
  return k;
}

bool contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// sigma_y = (A + B alpha^n)(1 + C ln(max(rate / rate_0, 1)))(1 - T*^m) (FlowStress.hpp).
void declareFlowStress(Teuchos::ParameterList& mat) {
  declareDouble(mat, "Johnson-Cook A", 0.0, "'Johnson-Cook': A, the initial yield stress [Pa] (required, > 0)",
                Range::nonNegative());
  declareDouble(mat, "Johnson-Cook B", 0.0, "'Johnson-Cook': B, the hardening coefficient [Pa]", Range::nonNegative());
  declareDouble(mat, "Johnson-Cook n", 1.0, "'Johnson-Cook': n, the hardening exponent, in (0, 1]",
                Range::positive());
  declareDouble(mat, "Johnson-Cook C", 0.0, "'Johnson-Cook': C, the strain-rate coefficient [-]",
                Range::nonNegative());
  declareDouble(mat, "Reference Strain Rate", 1.0,
                "'Johnson-Cook': the plastic strain rate below which the flow stress is the quasi-static "
                "one [1/s]",
                Range::positive());
  declareDouble(mat, "Johnson-Cook m", 1.0, "'Johnson-Cook': m, the thermal-softening exponent [-]",
                Range::positive());
  declareDouble(mat, "Reference Temperature", 20.0,
                "'Johnson-Cook': T_0, the temperature of the quasi-static flow stress (any temperature "
                "unit, the same for the three temperatures)");
  declareDouble(mat, "Melting Temperature", 0.0,
                "'Johnson-Cook': T_m, where the flow stress vanishes (required, above T_0)");
  declareDouble(mat, "Initial Temperature", 20.0, "'Johnson-Cook': the temperature at the start (below T_m)");
  declareDouble(mat, "Specific Heat", 0.0,
                "'Johnson-Cook': c [J/(kg K)] (required with heating): the plastic work's heat raises the "
                "temperature by chi dW_p / (rho c)",
                Range::nonNegative());
  declareDouble(mat, "Taylor-Quinney Coefficient", 0.9,
                "'Johnson-Cook': chi, the share of the plastic work that becomes heat (0: isothermal)",
                Range::closed(0.0, 1.0));
}

// eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln rate*) (1 + D5 T*), D = sum d alpha / eps_f
// (JohnsonCookDamage.hpp).
void declareDamage(Teuchos::ParameterList& mat) {
  declareChoice(mat, "Damage", "none", {"none", "Johnson-Cook"},
                "'Johnson-Cook' materials: 'Johnson-Cook' accumulates Johnson and Cook's damage D = sum "
                "d alpha / eps_f, eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln rate*) (1 + D5 T*), sigma* the "
                "stress triaxiality, rate* and T* the flow stress's; reported (the DAMAGE element variable, "
                "the log when D first reaches 1), not coupled: no softening, no element erosion");
  const char* terms[5][2] = {{"D1", "the failure strain's constant term [-] (>= 0)"},
                             {"D2", "the triaxiality term's factor [-] (>= 0; D1 + D2 > 0)"},
                             {"D3", "the triaxiality exponent's factor [-] (usually negative)"},
                             {"D4", "the strain-rate coefficient [-] (>= 0)"},
                             {"D5", "the temperature coefficient [-] (>= 0)"}};
  for (const auto& t : terms)  // D3 any sign; the others >= 0 (JohnsonCookDamage.hpp)
    declareDouble(mat, std::string("Johnson-Cook ") + t[0], 0.0, std::string("'Damage' = 'Johnson-Cook': ") + t[1],
                  std::string(t[0]) == "D3" ? Range::any() : Range::nonNegative());
}

bool damaged(const Teuchos::ParameterList& keys) { return keys.get<std::string>("Damage") == "Johnson-Cook"; }

class JohnsonCookLaw : public MaterialLaw {
 public:
  const char* name() const override { return "Johnson-Cook"; }
  std::string description() const override {
    return "and 'Johnson-Cook' (J2 with the Johnson-Cook flow stress, its strain rate and adiabatic heating) on "
           "either kinematics: additive split in small strain, multiplicative with Hencky elasticity in finite "
           "strain";
  }
  bool smallStrain() const override { return true; }
  bool finiteStrain() const override { return true; }
  bool dissipative() const override { return true; }
  void declare(Teuchos::ParameterList& mat) const override {
    declareFlowStress(mat);
    declareDamage(mat);
  }
  std::vector<std::string> keysRead(const Teuchos::ParameterList& keys) const override {
    std::vector<std::string> k = flowKeys();
    k.insert(k.end(), {"Kinematic Hardening Modulus", "Damage"});
    if (damaged(keys)) k.insert(k.end(), damageKeys().begin(), damageKeys().end());
    return k;
  }
  void checkKeys(const LawInput& in) const override {
    const auto missing = [&](const std::string& key) { return in.keys.getEntry(key).isDefault(); };
    if (missing("Johnson-Cook A"))
      throwInput(in.file, in.path + "Johnson-Cook A", "", "is missing: 'Johnson-Cook' needs A, the initial yield stress",
                 "give 'Johnson-Cook A' > 0 [Pa]");
    if (missing("Melting Temperature"))
      throwInput(in.file, in.path + "Melting Temperature", "",
                 "is missing: 'Johnson-Cook' needs the melting temperature of its thermal softening",
                 "give 'Melting Temperature' above 'Reference Temperature'");
  }
  void explainUnread(const LawInput& in, const std::string& key) const override {
    const std::string value = entryToString(in.keys.getEntry(key));
    if (contains(damageKeys(), key))
      throwInput(in.file, in.path + key, value, "is not a parameter of 'Johnson-Cook' with 'Damage' = 'none'",
                 "did you mean 'Damage' = 'Johnson-Cook'?");
    if (key == "Yield Stress" || key == "Hardening Modulus" || key == "Flow Curve")
      throwInput(in.file, in.path + key, value, "is not a parameter of 'Johnson-Cook'",
                 "the Johnson-Cook flow stress is (A + B alpha^n)(...): give 'Johnson-Cook A' and 'Johnson-Cook B', "
                 "or set 'Model' = 'J2 plasticity'");
  }
  bool explainForeign(const LawInput& in, const std::string& key, const std::string& other) const override {
    if (key != "Damage" && !contains(damageKeys(), key)) return false;
    if (key == "Damage" && !damaged(in.keys)) return true;  // 'none' says what the other law does
    if (damaged(in.keys))
      throwInput(in.file, in.path + "Damage", in.keys.get<std::string>("Damage"),
                 "Johnson-Cook damage needs the Johnson-Cook flow stress (its reference rate and temperatures); the "
                 "material's 'Model' is '" + other + "'",
                 "set 'Model' = 'Johnson-Cook', or 'Damage' = 'none'");
    throwInput(in.file, in.path + key, entryToString(in.keys.getEntry(key)), "is not a parameter of '" + other + "'",
               "did you mean 'Model' = 'Johnson-Cook' with 'Damage' = 'Johnson-Cook'?");
  }
  std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool finiteStrain) const override {
    J2Parameters p = j2Parameters(in, finiteStrain);
    const Teuchos::ParameterList& k = in.keys;
    p.johnsonCook = true;
    JohnsonCookParameters& jc = p.jc;
    jc.A = k.get<double>("Johnson-Cook A"), jc.B = k.get<double>("Johnson-Cook B");
    jc.n = k.get<double>("Johnson-Cook n"), jc.C = k.get<double>("Johnson-Cook C");
    jc.referenceRate = k.get<double>("Reference Strain Rate"), jc.m = k.get<double>("Johnson-Cook m");
    jc.referenceTemperature = k.get<double>("Reference Temperature");
    jc.meltingTemperature = k.get<double>("Melting Temperature");
    jc.initialTemperature = k.get<double>("Initial Temperature");
    jc.specificHeat = k.get<double>("Specific Heat");
    jc.taylorQuinney = k.get<double>("Taylor-Quinney Coefficient");
    jc.density = k.get<double>("Density");
    JohnsonCookDamageParameters& d = p.damage;
    d.enabled = damaged(k);
    d.D1 = k.get<double>("Johnson-Cook D1"), d.D2 = k.get<double>("Johnson-Cook D2");
    d.D3 = k.get<double>("Johnson-Cook D3"), d.D4 = k.get<double>("Johnson-Cook D4");
    d.D5 = k.get<double>("Johnson-Cook D5");
    return j2LawPoint(in, p, finiteStrain);
  }
};

}  // namespace

const MaterialLaw& johnsonCookLaw() {
  static const JohnsonCookLaw law;
  return law;
}

}  // namespace choc
