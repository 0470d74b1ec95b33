#include "analysis/AnalysisRegistry.hpp"

#include "analysis/ImplicitTransient.hpp"
#include "analysis/ModalAnalysis.hpp"
#include "analysis/ModalTransient.hpp"
#include "input/Errors.hpp"
#include "input/Validation.hpp"

namespace choc {

const std::vector<AnalysisType>& analysisTypes() {
  static const std::vector<AnalysisType> types = {
      {"Transient", "direct implicit transient: Newmark family (HHT, generalized-alpha), contact",
       &ImplicitTransient::parameters,
       [](const std::string& n, const Teuchos::ParameterList& p, const std::string& f) {
         return std::unique_ptr<Analysis>(new ImplicitTransient(n, p, f));
       }},
      {"Modal", "natural modes by Anasazi shift-invert (K x = lambda M x)",
       &ModalAnalysis::parameters,
       [](const std::string& n, const Teuchos::ParameterList& p, const std::string& f) {
         return std::unique_ptr<Analysis>(new ModalAnalysis(n, p, f));
       }},
      {"Modal Transient",
       "explicit transient on a modal basis with nonlinear shock links (DYNA_TRAN_MODAL)",
       &ModalTransient::parameters,
       [](const std::string& n, const Teuchos::ParameterList& p, const std::string& f) {
         return std::unique_ptr<Analysis>(new ModalTransient(n, p, f));
       }},
  };
  return types;
}

namespace {
const AnalysisType& typeOf(const Teuchos::ParameterList& a, const std::string& name,
                           const std::string& file) {
  std::vector<std::string> names;
  for (const auto& t : analysisTypes()) names.push_back(t.type);
  std::string all;
  for (const auto& n : names) all += (all.empty() ? "'" : ", '") + n + "'";
  const std::string param = "Analyses/" + name + "/Type";
  if (!a.isParameter("Type")) throwInput(file, param, "", "is required but missing", "valid: " + all);
  if (!a.isType<std::string>("Type")) throwInput(file, param, "", "must be a string", "valid: " + all);
  const std::string type = a.get<std::string>("Type");
  for (const auto& t : analysisTypes())
    if (t.type == type) return t;
  const std::string near = closestName(type, names);
  throwInput(file, param, type, "unknown analysis type",
             (near.empty() ? "" : "did you mean '" + near + "'? ") + "valid: " + all);
}
}  // namespace

void validateAnalyses(Teuchos::ParameterList& analyses, const std::string& inputFile) {
  if (analyses.numParams() == 0)
    throwInput(inputFile, "Analyses", "", "no analysis to run", "add at least one sublist with a Type");
  for (auto it = analyses.begin(); it != analyses.end(); ++it) {
    const std::string name = analyses.name(it);
    Teuchos::ParameterList& a = analyses.sublist(name);
    const AnalysisType& t = typeOf(a, name, inputFile);
    validate(a, t.parameters(), InputLocation{inputFile, "Analyses/" + name});
  }
}

std::vector<std::unique_ptr<Analysis>> createAnalyses(const Teuchos::ParameterList& analyses,
                                                      const std::string& inputFile) {
  std::vector<std::unique_ptr<Analysis>> out;
  for (auto it = analyses.begin(); it != analyses.end(); ++it) {
    const std::string name = analyses.name(it);
    const Teuchos::ParameterList& a = analyses.sublist(name);
    out.push_back(typeOf(a, name, inputFile).create(name, a, inputFile));
  }
  return out;
}

}  // namespace choc
