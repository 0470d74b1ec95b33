// One function per subcommand; each returns an exit code or throws InputError /
// NumericalError (turned into one stderr line and exit code 1 / 2 by runApplication).
#pragma once
#include <string>
#include <vector>

namespace choc {

int runRunCommand(const std::vector<std::string>& args);
int runCheckCommand(const std::vector<std::string>& args);
int runParametersCommand(const std::vector<std::string>& args);

}  // namespace choc
