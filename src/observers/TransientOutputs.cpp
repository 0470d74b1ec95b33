#include "observers/TransientOutputs.hpp"

#include "core/Log.hpp"
#include "input/ParameterSpec.hpp"
#include "observers/ExodusObserver.hpp"
#include "observers/InterruptObserver.hpp"
#include "observers/ProgressObserver.hpp"

namespace choc {

void declareTransientOutput(Teuchos::ParameterList& p) {
  declareString(p, "History", "",
                "recorded quantities '<node set>:<DX|DY|DZ|DRX|...|VX|...|AX|...>', e.g. 'A:DX A:VX'");
  declareInt(p, "Exodus Interval", 10,
             "write the Exodus fields every N steps and at the last step (0: no Exodus file)",
             Range::atLeast(0));
  declareDouble(p, "Progress Interval", 10.0,
                "print a progress line (simulated time, percent done, wall time, estimated time "
                "left) every this many seconds of wall time (0: none)",
                Range::nonNegative());
  declareEnergyBalance(p);
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
  return s;
}

const HistoryObserver& addTransientObservers(ObserverSet& set, const TransientOutputSettings& s,
                                             const OutputPlan& plan, const Model& model,
                                             const Teuchos::ParameterList& analysis) {
  auto history = std::make_unique<HistoryObserver>(plan.what, plan.columns,
                                                   plan.base + ".history.csv", analysis);
  const HistoryObserver& h = *history;
  set.add(std::move(history));
  if (s.exodusInterval > 0)
    set.add(std::make_unique<ExodusObserver>(plan.base + ".exo", model, h, s.exodusInterval));
  set.add(std::make_unique<ProgressObserver>(plan.startTime, plan.endTime, s.progressInterval));
  set.add(std::make_unique<InterruptObserver>(plan.what, model.rawComm(), plan.interruptEvery));
  return h;
}

}  // namespace choc
