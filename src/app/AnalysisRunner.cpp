#include "app/AnalysisRunner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include <Teuchos_CommHelpers.hpp>

#include "app/ErrorClass.hpp"
#include "core/CollectiveFailure.hpp"
#include "core/Errors.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/Resources.hpp"
#include "core/Version.hpp"
#include "output/Interrupt.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

std::string fileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(fnv1a(bytes.data(), bytes.size())));
  return buf;
}

namespace {

// Says which results of this run are partial (the writers renamed them *.incomplete.*).
void logPartialResults(const std::string& dir, double runStart) {
  if (!isRootRank()) return;
  std::vector<std::string> partial;
  for (const DirectoryEntry& e : listDirectory(dir))
    if (e.name.find(".incomplete") != std::string::npos && e.modified >= runStart - 2.0)
      partial.push_back(dir + "/" + e.name);
  std::sort(partial.begin(), partial.end());
  log() << "\nrun stopped; incomplete results of this run:";
  for (const auto& p : partial) log() << " " << p;
  log() << (partial.empty() ? " none\n" : "\n") << std::flush;
}

void describeRun(RunSummary& s, const Analysis& an, const std::string& type, const RunContext& ctx,
                 const RunFacts& facts) {
  s.set("analysis", an.name());
  s.set("type", type);
  s.set("choc/version", chocVersion());
  s.set("choc/commit", chocCommit());
  s.set("input/file", facts.inputFile);
  s.set("input/hash_fnv1a", facts.inputHash);
  s.set("ranks", ctx.model.comm()->getSize());
  s.set("unknowns", static_cast<long long>(ctx.model.dofs().numGlobal()));
}

// Peak memory and CPU time of every rank so far (collective).
void measureRanks(RunSummary& s, const Comm& comm) {
  const int n = comm.getSize();
  std::vector<double> mine(2 * n, 0.0), all(2 * n, 0.0);
  mine[comm.getRank()] = peakResidentBytes();
  mine[n + comm.getRank()] = cpuSeconds();
  Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_SUM, 2 * n, mine.data(), all.data());
  s.set("memory/peak_bytes_per_rank", std::vector<double>(all.begin(), all.begin() + n));
  s.set("cpu_seconds_per_rank", std::vector<double>(all.begin() + n, all.end()));
}

// The analysis's rows of checks.csv; returns how many failed.
int checksOf(RunSummary& s, const std::vector<CheckResult>& checks, const std::string& analysis) {
  int k = 0, failed = 0;
  for (const CheckResult& c : checks) {
    if (c.spec.analysis != analysis) continue;
    const std::string key = "checks/rows/" + std::to_string(++k);
    s.set(key + "/quantity", c.spec.quantity);
    s.set(key + "/time", c.spec.time);
    s.set(key + "/computed", c.computed);
    s.set(key + "/reference", c.spec.reference);
    s.set(key + "/error", c.error);
    s.set(key + "/tolerance", c.spec.tolerance);
    s.set(key + "/reference_kind", toString(c.spec.kind));
    s.set(key + "/criterion", toString(c.spec.criterion));
    s.set(key + "/status", c.ok ? "OK" : "NOOK");
    failed += c.ok ? 0 : 1;
  }
  s.set("checks/count", k);
  s.set("checks/failed", failed);
  return failed;
}

void write(const RunSummary& s, const OutputDirectory& out, const std::string& name) {
  const std::string path = out.file(name + suffix::summary);
  writeWholeFile(path, s.json(), true, path + ".incomplete");
}

// The summary of an analysis that completed: written by rank 0, a failure agreed on.
void writeCompleted(RunContext& ctx, const OutputDirectory& out, const std::string& name) {
  std::string failure;
  if (isRootRank()) {
    try {
      write(ctx.summary, out, name);
    } catch (const OutputError& e) {
      failure = e.what();
    }
  }
  failure = collectiveFailure(*ctx.model.comm(), failure);
  if (!failure.empty()) throw OutputError(failure);
}

// The summary of an analysis that stopped: rank 0's own figures only (no collective: the
// other ranks may have stopped elsewhere), best effort (the run's own error is the one to
// report).
void writeStopped(RunContext& ctx, const OutputDirectory& out, const std::string& name, const ErrorClass& c) {
  if (!isRootRank()) return;
  ctx.summary.set("status", c.kind == "interrupted" ? "interrupted" : "failed");
  ctx.summary.set("exit_code", c.exitCode);
  ctx.summary.set("reason", c.kind + ": " + c.message);
  // The per-rank figures of a completed run, rank 0's alone known (null for the others: a run
  // that stopped makes no collective call, the other ranks may have stopped elsewhere).
  const int ranks = ctx.model.comm()->getSize();
  std::vector<double> peak(size_t(ranks), NAN), cpu(size_t(ranks), NAN);
  peak[0] = peakResidentBytes(), cpu[0] = cpuSeconds();
  ctx.summary.set("memory/peak_bytes_per_rank", peak);
  ctx.summary.set("cpu_seconds_per_rank", cpu);
  try {
    write(ctx.summary, out, name);
  } catch (const std::exception&) {
    // The disk may be why the analysis stopped.
  }
}

}  // namespace

void runAnalyses(RunContext& ctx, const std::vector<std::unique_ptr<Analysis>>& analyses,
                 const Teuchos::ParameterList& input, const RunFacts& facts, const OutputDirectory& out) {
  const double runStart = wallClockSeconds();
  for (auto& an : analyses) {
    const std::string type = input.sublist("Analyses").sublist(an->name()).get<std::string>("Type");
    ctx.summary = RunSummary();
    describeRun(ctx.summary, *an, type, ctx, facts);
    const auto t0 = std::chrono::steady_clock::now();
    try {
      throwIfInterruptedBefore("analysis '" + an->name() + "'");
      log() << "\nanalysis '" << an->name() << "' (" << type << ")\n";
      an->run(ctx);
    } catch (const std::exception& e) {
      ctx.summary.set("wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      writeStopped(ctx, out, an->name(), classifyError(e));
      logPartialResults(ctx.outputDir, runStart);
      throw;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    log() << "  done in " << s << " s\n";
    const int failed = checksOf(ctx.summary, ctx.checks, an->name());
    ctx.summary.set("status", failed > 0 ? "check failed" : "completed");
    ctx.summary.set("exit_code", failed > 0 ? int(kExitCheckFailed) : int(kExitOk));
    ctx.summary.set("wall_seconds", s);
    measureRanks(ctx.summary, *ctx.model.comm());
    writeCompleted(ctx, out, an->name());
  }
}

}  // namespace choc
