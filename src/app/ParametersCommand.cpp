#include <iostream>

#include "analysis/AnalysisRegistry.hpp"
#include "checks/HistoryCheck.hpp"
#include "physics/ModelInput.hpp"
#include "app/Commands.hpp"
#include "core/Errors.hpp"
#include "input/Validation.hpp"
#include "core/Log.hpp"

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
  out << "\nThe checks of a transient (Analyses/<name>/Checks/<name>):\n";
  printCheckKinds(out, "  ");
  return kExitOk;
}

}  // namespace choc
