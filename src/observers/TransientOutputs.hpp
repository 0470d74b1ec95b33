// The output parameters both transients share and the standard set of observers built from
// them: history (memory and <name>.history.csv), Exodus (<name>.exo every 'Exodus Interval'
// states and the last), progress lines every 'Progress Interval' seconds of wall time, and
// the interrupt test. Keys of earlier releases ('Write Exodus' and 'Log Interval' of the
// direct transient, 'Progress Lines' of the modal transient) still work for this release,
// with a deprecation warning.
#pragma once
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "observers/CheckpointObserver.hpp"
#include "observers/HistoryObserver.hpp"
#include "observers/ImpactObserver.hpp"
#include "observers/RunLimits.hpp"
#include "physics/Model.hpp"

namespace choc {

// History, Exodus Interval, Progress Interval and the energy balance settings.
void declareTransientOutput(Teuchos::ParameterList& analysis);

// Rewrites the deprecated keys of an analysis list (before validation) into the current
// ones, logging one warning per key.
void translateDeprecatedOutputKeys(Teuchos::ParameterList& analysis, const std::string& file,
                                   const std::string& path);

struct TransientOutputSettings {
  std::string history;          // 'History': "A:DX A:VX"
  int exodusInterval = 10;      // 0: no Exodus file
  double progressInterval = 10; // seconds of wall time; 0: no progress lines
  CheckpointSettings checkpoint;
  RunLimits limits;
  EnergyBalanceSettings energy;
  ImpactSettings impacts;
};
TransientOutputSettings readTransientOutput(const Teuchos::ParameterList& analysis);

struct OutputPlan {
  std::string what;                  // "transient 'c1'", for messages
  std::string base;                  // "<output dir>/<analysis>"
  std::vector<std::string> columns;  // the history's columns after "time"
  double startTime = 0, endTime = 0;
  long long interruptEvery = 1;      // recorded states between two interrupt tests
  CheckpointPlan checkpoint;         // path, identity and the analysis's state (settings: from s)
  const StateArchive* resume = nullptr;  // continue a checkpointed run's files
};

// Throws the InputError a restart would meet when the history or the Exodus file of the
// checkpointed analysis (base "<dir>/<analysis>") is missing or shorter than the checkpoint
// needs, before anything is changed: a refused restart writes nothing.
void checkResumableOutputs(const std::string& base, const StateArchive& checkpoint, bool exodus);

// Adds history, Exodus, progress and checkpoint/interrupt observers, in that order; returns the
// history.
HistoryObserver& addTransientObservers(ObserverSet& set, const TransientOutputSettings& s,
                                             const OutputPlan& plan, const Model& model);

}  // namespace choc
