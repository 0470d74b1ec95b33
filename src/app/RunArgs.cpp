#include "app/RunArgs.hpp"

#include <algorithm>

#include "core/Errors.hpp"
#include "output/OutputDirectory.hpp"

namespace choc {

namespace {
const char* const kRunUsageHead =
    "usage: choc run INPUT.xml [-o DIR] [--restart FILE.checkpoint]\n"
    "  runs every analysis of INPUT.xml\n"
    "  -o, --output DIR          results in DIR (default results/<input name>/); one run at a\n"
    "                            time per directory (a second is refused while one runs)\n"
    "  --restart FILE.checkpoint continue the transient that wrote FILE (same input and mesh;\n"
    "                            'End Time' may be raised; any number of ranks)\n"
    "  -h, --help                this text\n"
    "exit codes: 0 success, 1 input error, 2 numerical failure, out of memory or a result that\n"
    "            cannot be written, 3 a declared check failed or energy created, 4 internal\n"
    "            error, 130/143 interrupted by SIGINT/SIGTERM (see 'choc --help')\n";
}  // namespace

std::string runUsage() {
  std::string u = kRunUsageHead;
  u += "each analysis <name> writes in DIR (a failed one leaves <name>.incomplete.<ext>):\n";
  for (const OutputFileKind& k : analysisOutputKinds()) {
    std::string line = "  <name>" + k.suffix;
    line.resize(std::max<std::size_t>(line.size() + 1, 28), ' ');
    u += line + k.description + "\n";
  }
  return u + "  checks.csv                one row per declared check (and per failed energy check)\n";
}

const char* kCheckUsage =
    "usage: choc check INPUT.xml\n"
    "  validates the input, sets every analysis up (every node set, side set, probe, basis,\n"
    "  pair and solver choice resolved) and prints the resolved parameter list with defaults\n";

RunArgs parseRunArgs(const std::vector<std::string>& args, const std::string& cmd) {
  RunArgs r;
  const std::string valid = cmd == "run" ? "valid: -o DIR, --restart FILE, --help" : "valid: --help";
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-h" || args[i] == "--help") {
      r.help = true;
    } else if ((args[i] == "-o" || args[i] == "--output") && cmd == "run") {
      if (i + 1 >= args.size()) throw InputError("choc " + cmd + ": option -o needs a directory");
      r.outputDir = args[++i];
      if (r.outputDir.empty()) throw InputError("choc run: option -o: the directory name is empty");
    } else if (args[i] == "--restart" && cmd == "run") {
      if (i + 1 >= args.size()) throw InputError("choc run: option --restart needs a checkpoint file");
      r.restart = args[++i];
    } else if (!args[i].empty() && args[i][0] == '-') {
      throw InputError("choc " + cmd + ": unknown option '" + args[i] + "'; " + valid);
    } else if (r.input.empty()) {
      r.input = args[i];
    } else {
      throw InputError("choc " + cmd + ": one input file expected, got '" + r.input + "' and '" +
                       args[i] + "'");
    }
  }
  if (r.input.empty() && !r.help)
    throw InputError("choc " + cmd + ": missing INPUT.xml (usage: choc " + cmd + " INPUT.xml)");
  return r;
}

}  // namespace choc
