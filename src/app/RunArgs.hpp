// The command line of `choc run` and `choc check`: the input, -o DIR, --restart FILE, --help.
#pragma once
#include <string>
#include <vector>

namespace choc {

struct RunArgs {
  std::string input, outputDir, restart;
  bool help = false;
};

std::string runUsage();  // with the files an analysis writes (analysisOutputKinds())
extern const char* kCheckUsage;

// Throws InputError (one line) for an unknown option, a missing value or input, two inputs.
RunArgs parseRunArgs(const std::vector<std::string>& args, const std::string& cmd);

}  // namespace choc
