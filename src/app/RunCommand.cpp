#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>

#include <Tpetra_Core.hpp>

#include "analysis/AnalysisRegistry.hpp"
#include "app/Commands.hpp"
#include "app/InputDeck.hpp"
#include "core/Errors.hpp"
#include "core/Resources.hpp"
#include "output/Checks.hpp"
#include "output/Interrupt.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "restart/CheckpointFile.hpp"
#include "restart/RunIdentity.hpp"

namespace choc {

namespace {

struct RunArgs {
  std::string input, outputDir, restart;
};

RunArgs parseRunArgs(const std::vector<std::string>& args, const std::string& cmd) {
  RunArgs r;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o" || args[i] == "--output") {
      if (i + 1 >= args.size()) throw InputError("choc " + cmd + ": option -o needs a directory");
      r.outputDir = args[++i];
    } else if (args[i] == "--restart" && cmd == "run") {
      if (i + 1 >= args.size()) throw InputError("choc run: option --restart needs a checkpoint file");
      r.restart = args[++i];
    } else if (!args[i].empty() && args[i][0] == '-') {
      throw InputError("choc " + cmd + ": unknown option '" + args[i] + "'; valid: -o DIR");
    } else if (r.input.empty()) {
      r.input = args[i];
    } else {
      throw InputError("choc " + cmd + ": one input file expected, got '" + r.input + "' and '" +
                       args[i] + "'");
    }
  }
  if (r.input.empty()) throw InputError("choc " + cmd + ": missing INPUT.xml (usage: choc " + cmd + " INPUT.xml)");
  return r;
}

// Two log lines: the peak memory of every rank and the total per unknown; the CPU time of
// every rank (on a loaded machine the wall time of several ranks says little; the CPU time
// says what each rank computed).
void logResources(const Teuchos::Comm<int>& comm, long long unknowns) {
  const int n = comm.getSize();
  std::vector<double> mine(2 * n, 0.0), all(2 * n, 0.0);
  mine[comm.getRank()] = peakResidentBytes();
  mine[n + comm.getRank()] = cpuSeconds();
  Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_SUM, 2 * n, mine.data(), all.data());
  double total = 0.0;
  std::string per, cpu;
  for (int r = 0; r < n; ++r) {
    total += all[r];
    char s[32];
    std::snprintf(s, sizeof s, "%s%.1f", per.empty() ? "" : " ", all[r] / 1048576.0);
    per += s;
    std::snprintf(s, sizeof s, "%s%.2f", cpu.empty() ? "" : " ", all[n + r]);
    cpu += s;
  }
  char line[160];
  std::snprintf(line, sizeof line, "; all ranks %.1f MiB, %.0f bytes per unknown\n", total / 1048576.0,
                unknowns > 0 ? total / double(unknowns) : 0.0);
  log() << "memory: peak resident per rank [MiB]: " << per << line;
  log() << "cpu time per rank [s]: " << cpu << "\n";
}

// The checkpoint of --restart, refused (one line, exit 1) unless this input and mesh wrote it
// and it is before the analysis's end time.
std::shared_ptr<const StateArchive> loadRestart(const std::string& file, const Teuchos::ParameterList& input,
                                                const std::string& inputFile, const Model& model) {
  auto archive = std::make_shared<StateArchive>(readCheckpointFile(file));
  const auto refuse = [&](const std::string& why) {
    throw InputError(file + ": option '--restart': " + why);
  };
  RunIdentity was;
  try {
    was = RunIdentity::load(*archive);
  } catch (const StateRecordError& e) {
    refuse(std::string("not a checkpoint of a transient (") + e.what() + ")");
  }
  const Teuchos::ParameterList& analyses = input.sublist("Analyses");
  if (!analyses.isSublist(was.analysis))
    refuse("written by analysis '" + was.analysis + "', which " + inputFile + " does not have");
  RunIdentity now;
  now.analysis = was.analysis;
  now.input = canonicalInput(input, was.analysis);
  now.mesh = meshHash(model.mesh());
  now.ranks = model.comm()->getSize();
  const std::string differs = was.mismatch(now);
  if (!differs.empty()) refuse("written by another input or mesh: " + differs);
  const Teuchos::ParameterList& an = analyses.sublist(was.analysis);
  const double t = archive->getDouble("point/time"), end = an.get<double>("End Time");
  if (!(t < end))
    refuse(format("the checkpoint is at t = %.6e s, not before 'Analyses/%s/End Time' = %.6e s; "
                  "raise End Time to continue the run",
                  t, was.analysis.c_str(), end));
  log() << format("restart: analysis '%s' continues from %s (t = %.6e s, written on %d rank(s))\n",
                  was.analysis.c_str(), file.c_str(), t, was.ranks);
  return archive;
}

}  // namespace

int runRunCommand(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  RunArgs a = parseRunArgs(args, "run");
  auto input = readAndValidateInput(a.input);
  if (a.outputDir.empty())
    a.outputDir = "results/" + std::filesystem::path(a.input).stem().string();
  auto comm = Tpetra::getDefaultComm();
  log() << "choc run " << a.input << ": " << input->get<std::string>("Title") << "\n";
  Model model(*input, a.input, comm);
  log() << "model: " << model.mesh().numNodes() << " nodes, " << model.mesh().numElements()
        << " elements, " << model.dofs().numGlobal() << " unknowns on " << comm->getSize()
        << " rank(s)\n";
  std::shared_ptr<const StateArchive> restart;
  if (!a.restart.empty()) restart = loadRestart(a.restart, *input, a.input, model);
  auto analyses = createAnalyses(input->sublist("Analyses"), a.input);
  setupAnalyses(analyses, model);
  if (isRootRank()) {
    std::error_code ec;
    std::filesystem::create_directories(a.outputDir, ec);
    if (ec) throw InputError("choc run: cannot create output directory '" + a.outputDir + "': " + ec.message());
  }
  comm->barrier();
  RunContext ctx{model, a.outputDir, {}, {}, input.get(), restart};
  const std::string checksPath = a.outputDir + "/checks.csv";
  std::filesystem::remove(checksPath);
  // Results of an earlier run under the names this run writes would pass for this run's if
  // it fails before writing them: remove them first.
  // (Not those of the analysis a restart continues.)
  if (isRootRank())
    for (auto& an : analyses)
      for (const char* ext : {".exo", ".incomplete.exo", ".exo.part", ".history.csv",
                              ".history.incomplete.csv", ".history.csv.part", ".modes.csv",
                              ".modes.incomplete.csv", ".modes.csv.part", ".checkpoint"}) {
        if (restart && restart->text("identity/analysis") == an->name()) break;
        std::error_code ignored;
        std::filesystem::remove(a.outputDir + "/" + an->name() + ext, ignored);
      }
  const auto runStart = std::filesystem::file_time_type::clock::now();
  try {
    for (auto& an : analyses) {
      throwIfInterruptedBefore("analysis '" + an->name() + "'");
      const std::string type = input->sublist("Analyses").sublist(an->name()).get<std::string>("Type");
      log() << "\nanalysis '" << an->name() << "' (" << type << ")\n";
      const auto t0 = std::chrono::steady_clock::now();
      an->run(ctx);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      log() << "  done in " << s << " s\n";
    }
  } catch (...) {
    // Say which results of this run are partial (the writers renamed them *.incomplete.*).
    if (isRootRank()) {
      std::vector<std::string> partial;
      std::error_code ec;
      for (const auto& e : std::filesystem::directory_iterator(a.outputDir, ec)) {
        const std::string n = e.path().filename().string();
        std::error_code ec2;
        if (n.find(".incomplete") != std::string::npos && e.last_write_time(ec2) >= runStart - std::chrono::seconds(2))
          partial.push_back(e.path().string());
      }
      std::sort(partial.begin(), partial.end());
      log() << "\nrun stopped; incomplete results of this run:";
      for (const auto& p : partial) log() << " " << p;
      log() << (partial.empty() ? " none\n" : "\n") << std::flush;
    }
    throw;
  }
  if (!ctx.checks.empty()) {
    if (isRootRank()) {
      ChecksCsv csv(checksPath);
      csv.appendResults(ctx.checks);
      csv.finish();
    }
    log() << "\nchecks (" << checksPath << "):\n" << formatCheckTable(ctx.checks);
  }
  logResources(*comm, model.dofs().numGlobal());
  const double total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log() << "\nresults in " << a.outputDir << "/ (" << total << " s)\n";
  if (ctx.failedChecks()) {
    log() << "some checks are NOOK\n";
    return kExitCheckFailed;
  }
  return kExitOk;
}

int runCheckCommand(const std::vector<std::string>& args) {
  RunArgs a = parseRunArgs(args, "check");
  auto input = readAndValidateInput(a.input);
  auto comm = Tpetra::getDefaultComm();
  Model model(*input, a.input, comm);
  // Settings and setup of every analysis: every reference error `choc run` would report.
  setupAnalyses(createAnalyses(input->sublist("Analyses"), a.input), model);
  log() << "# " << a.input << " is valid: " << model.mesh().numNodes() << " nodes, "
        << model.dofs().numGlobal() << " unknowns\n";
  input->print(log(), Teuchos::ParameterList::PrintOptions().indent(2).showTypes(true).showDoc(false));
  return kExitOk;
}

}  // namespace choc
