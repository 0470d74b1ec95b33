#include "app/InputDeck.hpp"

#include "analysis/AnalysisRegistry.hpp"
#include "physics/ModelInput.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"

namespace choc {

Teuchos::RCP<Teuchos::ParameterList> readAndValidateInput(const std::string& path) {
  auto pl = readXmlParameters(path);
  validate(*pl, topLevelParameters(), InputLocation{path, ""});
  validateAnalyses(pl->sublist("Analyses"), path);
  return pl;
}

}  // namespace choc
