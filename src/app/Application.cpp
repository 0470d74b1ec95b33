#include "app/Application.hpp"

#include <iostream>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "app/Commands.hpp"
#include "app/ErrorClass.hpp"
#include "app/MeshCommand.hpp"
#include "core/Errors.hpp"
#include "output/Interrupt.hpp"
#include "core/Log.hpp"

namespace choc {

namespace {

const char* kUsage =
    "usage: choc <command> [arguments]\n"
    "  run INPUT.xml [-o DIR]   run every analysis of the input (results in DIR, default\n"
    "                           results/<input name>/; choc run --help for its options)\n"
    "  run INPUT.xml --restart F.checkpoint\n"
    "                           continue a transient from its checkpoint (the same input,\n"
    "                           'End Time' may be raised; any number of ranks)\n"
    "  check INPUT.xml          validate the input and print the resolved parameter list\n"
    "  parameters [--format text|markdown]\n"
    "                           print every valid parameter with its documentation\n"
    "  mesh [options] -o F.exo  generate a bar-impact mesh (choc mesh --help)\n"
    "  --help                   this text\n"
    "exit codes: 0 success, 1 input error, 2 numerical failure, out of memory or a result\n"
    "            that cannot be written (disk full, file-size limit), 3 a declared check\n"
    "            failed (or energy created beyond 'Energy Balance Tolerance'),\n"
    "            4 internal error, 130 interrupted by SIGINT, 143 interrupted by SIGTERM\n"
    "            (a failed or interrupted run stops at a step boundary and leaves its partial\n"
    "            results as <name>.incomplete.<ext>, listed in the log, and a transient\n"
    "            its last checkpoint <name>.checkpoint)\n";

// One line always: a message relayed from a library (Teuchos, Anasazi) may span several.
void reportError(const std::string& kind, const std::string& message) {
  std::string line;
  bool broken = false;  // inside a run of line breaks and the blanks that follow them
  for (char c : message) {
    if (c == '\n' || c == '\r') {
      broken = true;
      continue;
    }
    if (broken && (c == ' ' || c == '\t')) continue;
    if (broken && !line.empty() && line.back() != ' ') line += ' ';
    broken = false;
    line += c;
  }
  if (isRootRank()) std::cerr << "choc: " << kind << ": " << line << std::endl;
}

}  // namespace

int runApplication(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // Kokkos would answer --help itself: it sees the program name only.
  int scopeArgc = 1;
  Tpetra::ScopeGuard scope(&scopeArgc, &argv);
  // The handlers are in place since before main (src/main.cpp); again after MPI_Init, which may
  // install handlers of its own.
  installInterruptHandlers();
  if (args.empty()) {
    if (isRootRank()) std::cerr << kUsage;
    return kExitInputError;
  }
  const std::string cmd = args[0];
  std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      log() << kUsage;
      return kExitOk;
    }
    if (cmd == "run") return runRunCommand(rest);
    if (cmd == "check") return runCheckCommand(rest);
    if (cmd == "parameters") return runParametersCommand(rest);
    if (cmd == "mesh") return runMeshCommand(rest);
    throw InputError("unknown command '" + cmd + "'; valid: run, check, parameters, mesh, --help");
  } catch (const std::exception& e) {
    const ErrorClass c = classifyError(e);
    reportError(c.kind, c.message);
    return c.exitCode;
  }
}

}  // namespace choc
