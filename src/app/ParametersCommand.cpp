#include <iostream>

#include "analysis/AnalysisRegistry.hpp"
#include "analysis/ModelInput.hpp"
#include "app/Commands.hpp"
#include "input/Errors.hpp"
#include "input/Validation.hpp"
#include "output/Log.hpp"

namespace choc {

int runParametersCommand(const std::vector<std::string>& args) {
  if (!args.empty()) throw InputError("choc parameters: takes no argument (got '" + args[0] + "')");
  std::ostream& out = log();
  out << "choc input parameters (Teuchos XML parameter list)\n\n";
  printValidParameters(out, topLevelParameters());
  for (const auto& t : analysisTypes()) {
    out << "\nAnalyses/<name> with Type = '" << t.type << "': " << t.doc << "\n";
    printValidParameters(out, t.parameters(), "  ");
  }
  return kExitOk;
}

}  // namespace choc
