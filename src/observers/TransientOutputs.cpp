#include "observers/TransientOutputs.hpp"

#include "output/OutputDirectory.hpp"
#include "core/Log.hpp"
#include "input/ParameterSpec.hpp"
#include "observers/ExodusObserver.hpp"
#include "observers/ImpactObserver.hpp"
#include "observers/ProgressObserver.hpp"
#include "observers/RunLimits.hpp"
#include "output/ExodusResults.hpp"
#include "output/HistoryCsv.hpp"

namespace choc {

void declareTransientOutput(Teuchos::ParameterList& p) {
  declareString(p, "History", "",
                "recorded quantities '<node set>:<DX|DY|DZ|DRX|...|VX|...|AX|...>' (at the set's first "
                "node), e.g. 'A:DX A:VX'; in a 'Transient', also the whole set's linear momentum "
                "'<node set>:<PX|PY|PZ>' [kg m/s] and angular momentum about its centre of mass "
                "'<node set>:<LX|LY|LZ>' [kg m2/s] (3D and plane strain; M v with the analysis' mass "
                "matrix)");
  declareInt(p, "Exodus Interval", 10,
             "write the Exodus fields every N steps and at the last step (0: no Exodus file)",
             Range::atLeast(0));
  declareDouble(p, "Progress Interval", 10.0,
                "print a progress line (simulated time, percent done, wall time, estimated time "
                "left) every this many seconds of wall time (0: none)",
                Range::nonNegative());
  declareEnergyBalance(p);
  declareImpactStatistics(p);
  declareRunLimits(p);
  Teuchos::ParameterList& c = declareSublist(
      p, "Checkpoint",
      "checkpoints <analysis>.checkpoint (the state to continue the run with 'choc run INPUT "
      "--restart FILE'); one is always written on SIGINT/SIGTERM");
  declareInt(c, "Interval Steps", 0, "write a checkpoint every N steps (0: not by step count)",
             Range::atLeast(0));
  declareDouble(c, "Interval Seconds", 0.0,
                "write a checkpoint when this many seconds of wall time have passed since the "
                "last one (0: not by wall time)",
                Range::nonNegative());
}

namespace {

void warnDeprecated(const std::string& file, const std::string& path, const std::string& key,
                    const std::string& instead) {
  log() << "choc: warning: " << file << ": parameter '" << path << "/" << key
        << "' is deprecated and will be removed in the next release; " << instead << "\n";
}

}  // namespace

void translateDeprecatedOutputKeys(Teuchos::ParameterList& a, const std::string& file,
                                   const std::string& path) {
  if (a.isType<bool>("Write Exodus")) {
    warnDeprecated(file, path, "Write Exodus", "use 'Exodus Interval' (0: no Exodus file)");
    if (!a.get<bool>("Write Exodus")) a.set("Exodus Interval", 0);
    a.remove("Write Exodus");
  }
  for (const char* key : {"Log Interval", "Progress Lines"}) {
    if (!a.isType<int>(key)) continue;
    warnDeprecated(file, path, key,
                   "progress is printed every 'Progress Interval' seconds of wall time (0: none)");
    if (a.get<int>(key) == 0 && !a.isParameter("Progress Interval")) a.set("Progress Interval", 0.0);
    a.remove(key);
  }
}

TransientOutputSettings readTransientOutput(const Teuchos::ParameterList& p) {
  TransientOutputSettings s;
  s.history = p.get<std::string>("History");
  s.exodusInterval = p.get<int>("Exodus Interval");
  s.progressInterval = p.get<double>("Progress Interval");
  s.checkpoint.intervalSteps = p.sublist("Checkpoint").get<int>("Interval Steps");
  s.checkpoint.intervalSeconds = p.sublist("Checkpoint").get<double>("Interval Seconds");
  s.limits = readRunLimits(p);
  s.energy = readEnergyBalance(p);
  s.impacts = readImpactSettings(p);
  return s;
}

void checkResumableOutputs(const std::string& base, const StateArchive& checkpoint, bool exodus) {
  HistoryCsv::checkResumable(base + suffix::history, checkpoint.getInt("history/bytes"));
  if (exodus)
    ExodusResultsWriter::checkResumable(base + suffix::exodus, static_cast<int>(checkpoint.getInt("exodus/steps")));
}

HistoryObserver& addTransientObservers(ObserverSet& set, const TransientOutputSettings& s,
                                             const OutputPlan& plan, const Model& model) {
  const std::string csv = plan.base + suffix::history;
  auto history = plan.resume ? std::make_unique<HistoryObserver>(plan.what, plan.columns, csv, s.energy,
                                                                 *plan.resume, *model.comm())
                             : std::make_unique<HistoryObserver>(plan.what, plan.columns, csv, s.energy);
  HistoryObserver& h = *history;
  h.setRanks(model.comm()->getSize());
  set.add(std::move(history));
  set.add(std::make_unique<ImpactObserver>(plan.base + suffix::impacts, s.impacts, h, plan.resume));
  if (s.exodusInterval > 0)
    set.add(std::make_unique<ExodusObserver>(plan.base + suffix::exodus, model, h, s.exodusInterval, plan.resume));
  set.add(std::make_unique<ProgressObserver>(plan.startTime, plan.endTime, s.progressInterval));
  CheckpointPlan cp = plan.checkpoint;
  cp.settings = s.checkpoint;
  set.add(std::make_unique<CheckpointObserver>(plan.what, model.rawComm(), plan.interruptEvery,
                                               std::move(cp), set, &h));
  return h;
}

}  // namespace choc
