#include "physics/MaterialKeys.hpp"

#include <algorithm>
#include <vector>

#include "core/Errors.hpp"
#include "input/Validation.hpp"

namespace choc {

namespace {

using Keys = std::vector<std::string>;

const Keys& commonKeys() {
  static const Keys k{"Young's Modulus", "Poisson's Ratio", "Density", "Model"};
  return k;
}

const Keys& j2Keys() {
  static const Keys k{"Yield Stress", "Hardening Modulus", "Kinematic Hardening Modulus", "Flow Curve"};
  return k;
}

const Keys& johnsonCookKeys() {
  static const Keys k{"Johnson-Cook A",      "Johnson-Cook B",         "Johnson-Cook n",
                      "Johnson-Cook C",      "Reference Strain Rate",  "Johnson-Cook m",
                      "Reference Temperature", "Melting Temperature",  "Initial Temperature",
                      "Specific Heat",       "Taylor-Quinney Coefficient", "Kinematic Hardening Modulus",
                      "Damage"};
  return k;
}

const Keys& damageKeys() {
  static const Keys k{"Johnson-Cook D1", "Johnson-Cook D2", "Johnson-Cook D3", "Johnson-Cook D4",
                      "Johnson-Cook D5"};
  return k;
}

bool contains(const Keys& keys, const std::string& name) {
  return std::find(keys.begin(), keys.end(), name) != keys.end();
}

// The keys `law` reads (with `damage`: Johnson-Cook's damage fit too).
Keys keysRead(const std::string& law, bool damage) {
  Keys k = commonKeys();
  const Keys* extra = law == "J2 plasticity" ? &j2Keys() : law == "Johnson-Cook" ? &johnsonCookKeys() : nullptr;
  if (extra) k.insert(k.end(), extra->begin(), extra->end());
  if (law == "Johnson-Cook" && damage) k.insert(k.end(), damageKeys().begin(), damageKeys().end());
  return k;
}

// What would make `key` read: the law (or the damage switch) that reads it.
std::string readerOf(const std::string& key, const std::string& law) {
  if (contains(damageKeys(), key))
    return law == "Johnson-Cook" ? "did you mean 'Damage' = 'Johnson-Cook'?"
                                 : "did you mean 'Model' = 'Johnson-Cook' with 'Damage' = 'Johnson-Cook'?";
  if (contains(j2Keys(), key) && contains(johnsonCookKeys(), key))
    return "did you mean 'Model' = 'J2 plasticity' or 'Johnson-Cook'?";
  if (contains(j2Keys(), key))
    return law == "Johnson-Cook" ? "the Johnson-Cook flow stress is (A + B alpha^n)(...): give 'Johnson-Cook A' and "
                                   "'Johnson-Cook B', or set 'Model' = 'J2 plasticity'"
                                 : "did you mean 'Model' = 'J2 plasticity'?";
  return "did you mean 'Model' = 'Johnson-Cook'?";
}

void checkMissing(const std::string& file, const std::string& path, const std::string& law,
                  const Teuchos::ParameterList& mp) {
  const auto missing = [&](const std::string& key) { return mp.getEntry(key).isDefault(); };
  if (law == "J2 plasticity" && missing("Yield Stress") && missing("Flow Curve"))
    throwInput(file, path + "Yield Stress", "", "is missing: 'J2 plasticity' needs the initial yield stress",
               "give 'Yield Stress' > 0 [Pa], or a 'Flow Curve'");
  if (law != "Johnson-Cook") return;
  if (missing("Johnson-Cook A"))
    throwInput(file, path + "Johnson-Cook A", "", "is missing: 'Johnson-Cook' needs A, the initial yield stress",
               "give 'Johnson-Cook A' > 0 [Pa]");
  if (missing("Melting Temperature"))
    throwInput(file, path + "Melting Temperature", "",
               "is missing: 'Johnson-Cook' needs the melting temperature of its thermal softening",
               "give 'Melting Temperature' above 'Reference Temperature'");
}

}  // namespace

void checkMaterialKeys(const std::string& file, const std::string& materialName, const Teuchos::ParameterList& mp) {
  const std::string path = "Model/Materials/" + materialName + "/";
  const std::string law = mp.get<std::string>("Model");
  const bool damage = mp.get<std::string>("Damage") != "none";
  if (damage && law != "Johnson-Cook") return;  // refused with its own message (Model::strainKernel)
  const Keys read = keysRead(law, damage);
  for (auto it = mp.begin(); it != mp.end(); ++it) {
    const std::string& key = mp.name(it);
    if (mp.entry(it).isDefault() || contains(read, key)) continue;
    if (key == "Damage" && mp.get<std::string>(key) == "none") continue;  // says what the law does
    throwInput(file, path + key, entryToString(mp.entry(it)),
               "is not a parameter of '" + law + "'" +
                   (law == "Johnson-Cook" && contains(damageKeys(), key) ? " with 'Damage' = 'none'" : ""),
               readerOf(key, law));
  }
  checkMissing(file, path, law, mp);
}

}  // namespace choc
