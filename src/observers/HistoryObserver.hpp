// The history of a transient: probes, energies (with the energy balance) and the
// interactions' columns at every recorded state, kept in memory for the checks and written
// to <analysis>.history.csv by rank 0. A value that is not finite stops the run with a
// NumericalError naming the column and the time.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "observers/EnergyBalance.hpp"
#include "observers/HourglassMonitor.hpp"
#include "observers/TransientObserver.hpp"
#include "output/HistoryCsv.hpp"
#include "output/RunSummary.hpp"
#include "output/RecordedHistory.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

// energy:kinetic, energy:strain, energy:contact, energy:dissipated, energy:total, energy:balance.
const std::vector<std::string>& energyColumns();

// The history's columns after "time": probes, energies (with `plastic`, energy:plastic after
// energy:dissipated: the plastic work, a part of it; with `hourglass`, energy:hourglass next: the
// one-point elements' hourglass energy, a part of energy:strain), interactions.
std::vector<std::string> historyColumns(const std::vector<std::string>& probeColumns,
                                        const std::vector<std::string>& interactionColumns, bool plastic = false,
                                        bool hourglass = false);

class HistoryObserver : public TransientObserver {
 public:
  // what: "transient 'c1'" for messages; csvPath "" writes no file.
  HistoryObserver(std::string what, std::vector<std::string> columns, const std::string& csvPath,
                  const EnergyBalanceSettings& energy);
  // Continues a checkpointed run: the rows of the history file up to the checkpoint (read
  // by rank 0, shared with every rank) and the energy balance's state.
  HistoryObserver(std::string what, std::vector<std::string> columns, const std::string& csvPath,
                  const EnergyBalanceSettings& energy, const StateArchive& resume, const Comm& comm);
  void step(TransientView& view) override;
  void end(bool ok) override;
  void archive(StateArchive& a) const override;

  const RecordedHistory& history() const { return history_; }
  void setStatistics(std::map<std::string, double> s) { history_.statistics = std::move(s); }
  // On several ranks a failed write of the history (rank 0) is kept here until every rank
  // agrees to stop (CheckpointObserver); on one rank it is thrown at once.
  void setRanks(int ranks);
  const std::string& pendingFailure() const { return pending_; }
  const EnergyTerms& lastEnergies() const { return energies_; }
  const EnergyBalanceMonitor& balance() const { return balance_; }
  const HourglassMonitor& hourglass() const { return hourglassMonitor_; }
  // The energy balance and the impact statistics, for <analysis>.summary.json.
  void summarize(RunSummary& s) const;

 private:
  std::string what_;
  std::vector<std::string> columns_;
  std::unique_ptr<HistoryCsv> csv_;
  EnergyBalanceMonitor balance_;
  HourglassMonitor hourglassMonitor_;
  RecordedHistory history_;
  EnergyTerms energies_;
  std::string pending_;
  bool single_ = true;
  bool plastic_ = false;  // the energy:plastic column (models with plastic blocks)
  bool hourglass_ = false;  // the energy:hourglass column (models with one-point blocks)
};

}  // namespace choc
