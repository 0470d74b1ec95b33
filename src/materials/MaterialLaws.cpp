// The registry of material laws and the rules every material's keys follow (MaterialLaw.hpp).
#include <algorithm>
#include <stdexcept>

#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Validation.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

#define CHOC_MATERIAL_LAW(f) const MaterialLaw& f();
#include "materials/MaterialLaws.def"
#undef CHOC_MATERIAL_LAW

const std::vector<const MaterialLaw*>& materialLaws() {
#define CHOC_MATERIAL_LAW(f) &f(),
  static const std::vector<const MaterialLaw*> laws = {
#include "materials/MaterialLaws.def"
  };
#undef CHOC_MATERIAL_LAW
  return laws;
}

const MaterialLaw& materialLaw(const std::string& name) {
  for (const MaterialLaw* law : materialLaws())
    if (name == law->name()) return *law;
  throw std::out_of_range("no material law '" + name + "'");
}

ElasticConstants MaterialLaw::elasticConstants(const Teuchos::ParameterList& keys) const {
  return {keys.get<double>("Young's Modulus"), keys.get<double>("Poisson's Ratio")};
}

void declareMaterialLaws(Teuchos::ParameterList& mat) {
  declareDouble(mat, "Young's Modulus", 0.0, "E [Pa] (required by every law but 'Mooney-Rivlin')", Range::positive());
  declareDouble(mat, "Poisson's Ratio", 0.0, "nu [-]", {-1.0, 0.5, true, true});
  declareRequiredDouble(mat, "Density", "rho [kg/m^3]", Range::positive());
  std::vector<std::string> names;
  std::string doc = "the material law:";
  for (const MaterialLaw* law : materialLaws()) {
    names.push_back(law->name());
    doc += " " + law->description();
  }
  declareChoice(mat, "Model", "linear elastic", names, doc);
  for (const MaterialLaw* law : materialLaws()) law->declare(mat);
}

namespace {

bool contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

bool readsKey(const MaterialLaw& law, const std::string& key, const Teuchos::ParameterList& keys) {
  if (key == "Density" || key == "Model") return true;
  if (key == "Young's Modulus" || key == "Poisson's Ratio") return law.readsElasticConstants();
  return contains(law.keysRead(keys), key);
}

// "did you mean 'Model' = 'A', 'B' or 'C'?" over the laws that read `key` with these keys.
std::string readersOf(const std::string& key, const Teuchos::ParameterList& keys) {
  std::vector<std::string> readers;
  for (const MaterialLaw* law : materialLaws())
    if (readsKey(*law, key, keys)) readers.push_back("'" + std::string(law->name()) + "'");
  std::string text;
  for (size_t i = 0; i < readers.size(); ++i)
    text += (i == 0 ? "" : i + 1 == readers.size() ? " or " : ", ") + readers[i];
  return readers.empty() ? "" : "did you mean 'Model' = " + text + "?";
}

}  // namespace

void checkMaterialKeys(const std::string& file, const std::string& materialName, const Teuchos::ParameterList& mp) {
  const LawInput in{file, "Model/Materials/" + materialName + "/", mp};
  const MaterialLaw& law = materialLaw(mp.get<std::string>("Model"));
  for (auto it = mp.begin(); it != mp.end(); ++it) {
    const std::string& key = mp.name(it);
    if (mp.entry(it).isDefault() || readsKey(law, key, mp)) continue;
    law.explainUnread(in, key);
    bool harmless = false;
    for (const MaterialLaw* other : materialLaws()) harmless = other->explainForeign(in, key, law.name()) || harmless;
    if (harmless) continue;
    throwInput(file, in.path + key, entryToString(mp.entry(it)), "is not a parameter of '" + std::string(law.name()) + "'",
               readersOf(key, mp));
  }
  if (law.readsElasticConstants() && mp.getEntry("Young's Modulus").isDefault())
    throwInput(file, in.path + "Young's Modulus", "", "is required but missing", "add it (a number in (0, inf))");
  law.checkKeys(in);
}

}  // namespace choc
