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
#include "app/AnalysisRunner.hpp"
#include "app/InputDeck.hpp"
#include "app/RunArgs.hpp"
#include "core/CollectiveFailure.hpp"
#include "core/Errors.hpp"
#include "core/Files.hpp"
#include "core/Resources.hpp"
#include "observers/TransientOutputs.hpp"
#include "output/Checks.hpp"
#include "output/Interrupt.hpp"
#include "output/OutputDirectory.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "restart/CheckpointFile.hpp"
#include "restart/RunIdentity.hpp"

namespace choc {

namespace {

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

// Before anything is written: a restart's earlier results must be there to continue (a
// refused restart writes nothing), then the results of an earlier run under the names this
// run writes are removed, or they would pass for this run's if it failed before writing them
// (not those of the analysis a restart continues, nor the checkpoint it names). A file that
// cannot be removed is an input error naming it.
void prepareOutputs(const OutputDirectory& out, const std::vector<std::unique_ptr<Analysis>>& analyses,
                    const Teuchos::ParameterList& input, const StateArchive* restart,
                    const std::string& restartFile, const Comm& comm) {
  std::string failure;
  if (isRootRank()) {
    try {
      const std::string continued = restart ? restart->text("identity/analysis") : "";
      if (restart) {
        const auto& an = input.sublist("Analyses").sublist(continued);
        checkResumableOutputs(out.file(continued), *restart, an.get<int>("Exodus Interval") > 0);
      }
      for (const std::string& f : resultFileNames("checks.csv")) removeFile(out.file(f));
      for (const auto& an : analyses) {
        if (an->name() == continued) continue;
        for (const std::string& f : analysisOutputFiles(an->name()))
          if (restartFile.empty() || !sameFile(out.file(f), restartFile)) removeFile(out.file(f));
      }
    } catch (const std::exception& e) {  // InputError or OutputError: before the run, input
      failure = e.what();
    }
  }
  failure = collectiveFailure(comm, failure);
  if (!failure.empty()) throw InputError(failure);
}

void writeChecks(const RunContext& ctx, const OutputDirectory& out) {
  if (ctx.checks.empty()) return;
  const std::string path = out.file("checks.csv");
  std::string failure;
  if (isRootRank()) {
    try {
      writeChecksCsv(path, ctx.checks);
    } catch (const OutputError& e) {
      failure = e.what();
    }
  }
  failure = collectiveFailure(*ctx.model.comm(), failure);
  if (!failure.empty()) throw OutputError(failure);
  log() << "\nchecks (" << path << "):\n" << formatCheckTable(ctx.checks);
}

}  // namespace

int runRunCommand(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  RunArgs a = parseRunArgs(args, "run");
  if (a.help) {
    log() << runUsage();
    return kExitOk;
  }
  auto input = readAndValidateInput(a.input);
  if (a.outputDir.empty()) a.outputDir = "results/" + std::filesystem::path(a.input).stem().string();
  auto comm = Tpetra::getDefaultComm();
  const OutputDirectory out(a.outputDir, *comm);  // held until the run ends
  log() << "choc run " << a.input << ": " << input->get<std::string>("Title") << "\n";
  Model model(*input, a.input, comm);
  log() << "model: " << model.mesh().numNodes() << " nodes, " << model.mesh().numElements()
        << " elements, " << model.dofs().numGlobal() << " unknowns on " << comm->getSize()
        << " rank(s)\n";
  std::shared_ptr<const StateArchive> restart;
  if (!a.restart.empty()) restart = loadRestart(a.restart, *input, a.input, model);
  auto analyses = createAnalyses(input->sublist("Analyses"), a.input);
  setupAnalyses(analyses, model);
  throwIfInterruptedBefore("the first analysis (during the set-up)");
  prepareOutputs(out, analyses, *input, restart.get(), a.restart, *comm);
  RunContext ctx{model, out.path(), {}, {}, input.get(), restart, {}};
  runAnalyses(ctx, analyses, *input, RunFacts{a.input, fileHash(a.input)}, out);
  writeChecks(ctx, out);
  logResources(*comm, model.dofs().numGlobal());
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log() << "\nresults in " << out.path() << "/ (" << total << " s)\n";
  if (ctx.failedChecks()) {
    log() << "some checks are NOOK\n";
    return kExitCheckFailed;
  }
  return kExitOk;
}

int runCheckCommand(const std::vector<std::string>& args) {
  RunArgs a = parseRunArgs(args, "check");
  if (a.help) {
    log() << kCheckUsage;
    return kExitOk;
  }
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
