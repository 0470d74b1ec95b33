#include "analysis/AnalysisRegistry.hpp"

#include "analysis/DirectTransient.hpp"
#include "analysis/ModalAnalysis.hpp"
#include "analysis/ModalTransient.hpp"
#include "checks/HistoryCheck.hpp"
#include "core/Errors.hpp"
#include "input/OutputName.hpp"
#include "input/Validation.hpp"
#include "observers/TransientOutputs.hpp"

namespace choc {

namespace {
template <class A>
std::unique_ptr<Analysis> make(const std::string& n, const Teuchos::ParameterList& p, const std::string& f) {
  return std::make_unique<A>(n, p, f);
}
}  // namespace

const std::vector<AnalysisType>& analysisTypes() {
  static const std::vector<AnalysisType> types = {
      {"Transient", "direct implicit transient: Newmark family (HHT, generalized-alpha), contact",
       &DirectTransient::parameters,
       &make<DirectTransient>},
      {"Modal", "natural modes by Anasazi shift-invert (K x = lambda M x)",
       &ModalAnalysis::parameters,
       &make<ModalAnalysis>},
      {"Modal Transient",
       "explicit transient on a modal basis with nonlinear shock links (DYNA_TRAN_MODAL)",
       &ModalTransient::parameters,
       &make<ModalTransient>},
  };
  return types;
}

namespace {
const AnalysisType& typeOf(const Teuchos::ParameterList& a, const std::string& name,
                           const std::string& file) {
  std::vector<std::string> names;
  for (const auto& t : analysisTypes()) names.push_back(t.type);
  const std::string all = quotedNames(names);
  const std::string param = "Analyses/" + name + "/Type";
  if (!a.isParameter("Type")) throwInput(file, param, "", "is required but missing", "valid: " + all);
  if (!a.isType<std::string>("Type")) throwInput(file, param, "", "must be a string", "valid: " + all);
  const std::string type = a.get<std::string>("Type");
  for (const auto& t : analysisTypes())
    if (t.type == type) return t;
  throwInput(file, param, type, "unknown analysis type", didYouMean(type, names) + "valid: " + all);
}
}  // namespace

void validateAnalyses(Teuchos::ParameterList& analyses, const std::string& inputFile) {
  if (analyses.numParams() == 0)
    throwInput(inputFile, "Analyses", "", "no analysis to run", "add at least one sublist with a Type");
  for (auto it = analyses.begin(); it != analyses.end(); ++it) {
    const std::string name = analyses.name(it);
    checkOutputName(inputFile, "Analyses", name);  // it names the analysis's files
    Teuchos::ParameterList& a = analyses.sublist(name);
    const AnalysisType& t = typeOf(a, name, inputFile);
    const InputLocation where{inputFile, "Analyses/" + name};
    if (t.type != "Modal") {
      translateDeprecatedOutputKeys(a, inputFile, where.path);
      translateDeprecatedExactSolution(a, inputFile, where.path);
    }
    validate(a, t.parameters(), where);
    if (a.isSublist("Checks")) validateChecks(a.sublist("Checks"), where.child("Checks"));
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

void setupAnalyses(const std::vector<std::unique_ptr<Analysis>>& analyses, Model& model) {
  SetupContext ctx{model, {}};
  for (const auto& a : analyses) a->setup(ctx);
}

}  // namespace choc
