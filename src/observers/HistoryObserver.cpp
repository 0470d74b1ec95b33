#include "observers/HistoryObserver.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "core/CollectiveFailure.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace choc {

const std::vector<std::string>& energyColumns() {
  static const std::vector<std::string> names = {"energy:kinetic", "energy:strain",
                                                 "energy:contact", "energy:dissipated",
                                                 "energy:total",   "energy:balance"};
  return names;
}

std::vector<std::string> historyColumns(const std::vector<std::string>& probeColumns,
                                        const std::vector<std::string>& interactionColumns, bool plastic,
                                        bool hourglass) {
  std::vector<std::string> c = probeColumns;
  c.insert(c.end(), energyColumns().begin(), energyColumns().end());
  if (plastic) c.insert(c.end() - 2, "energy:plastic");  // after energy:dissipated
  if (hourglass) c.insert(c.end() - 2, "energy:hourglass");
  c.insert(c.end(), interactionColumns.begin(), interactionColumns.end());
  return c;
}

HistoryObserver::HistoryObserver(std::string what, std::vector<std::string> columns,
                                 const std::string& csvPath, const EnergyBalanceSettings& energy)
    : what_(std::move(what)), columns_(std::move(columns)), balance_(energy, what_), hourglassMonitor_(what_),
      plastic_(std::find(columns_.begin(), columns_.end(), "energy:plastic") != columns_.end()),
      hourglass_(std::find(columns_.begin(), columns_.end(), "energy:hourglass") != columns_.end()) {
  if (!csvPath.empty() && isRootRank()) csv_ = std::make_unique<HistoryCsv>(csvPath, columns_);
}

HistoryObserver::HistoryObserver(std::string what, std::vector<std::string> columns,
                                 const std::string& csvPath, const EnergyBalanceSettings& energy,
                                 const StateArchive& resume, const Comm& comm)
    : what_(std::move(what)), columns_(std::move(columns)), balance_(energy, what_), hourglassMonitor_(what_),
      plastic_(std::find(columns_.begin(), columns_.end(), "energy:plastic") != columns_.end()),
      hourglass_(std::find(columns_.begin(), columns_.end(), "energy:hourglass") != columns_.end()) {
  balance_.setState(resume.getPod<EnergyBalanceMonitor::State>("history/balance"));
  energies_ = resume.getPod<EnergyTerms>("history/energies");
  const auto rows = static_cast<std::size_t>(resume.getInt("history/rows"));
  std::vector<double> flat;  // rows x (1 + columns), time first
  std::string failure;
  if (isRootRank()) {
    try {
      std::string prefix;
      HistoryCsv::Resume at{rows, resume.getInt("history/bytes")};
      if (!csvPath.empty()) csv_ = std::make_unique<HistoryCsv>(csvPath, columns_, at, prefix);
      const HistoryTable t = parseHistoryCsv(prefix, csvPath);
      for (const auto& r : t.rows) flat.insert(flat.end(), r.begin(), r.end());
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  failure = collectiveFailure(comm, failure);
  if (!failure.empty()) throw InputError(failure);
  flat.resize(rows * (columns_.size() + 1));
  if (!flat.empty())
    Teuchos::broadcast<int, double>(comm, 0, static_cast<int>(flat.size()), flat.data());
  const std::size_t width = columns_.size() + 1;
  for (std::size_t i = 0; i < rows; ++i) {
    history_.times.push_back(flat[i * width]);
    for (std::size_t k = 0; k < columns_.size(); ++k)
      history_.columns[columns_[k]].push_back(flat[i * width + 1 + k]);
  }
  if (!hourglass_) return;
  const auto column = [&](const char* name, std::size_t i) {
    const auto c = history_.columns.find(name);
    return c == history_.columns.end() ? 0.0 : c->second[i];
  };
  for (std::size_t i = 0; i < rows; ++i)
    hourglassMonitor_.update(history_.times[i], column("energy:hourglass", i),
                             column("energy:strain", i) + column("energy:plastic", i), balance_.endReference(), true);
}

void HistoryObserver::setRanks(int ranks) { single_ = ranks == 1; }

void HistoryObserver::archive(StateArchive& a) const {
  a.putPod("history/balance", balance_.state());
  a.putPod("history/energies", energies_);
  a.putInt("history/rows", static_cast<long long>(history_.times.size()));
  a.putInt("history/bytes", csv_ ? csv_->flush() : 0);
}

void HistoryObserver::step(TransientView& view) {
  const StepPoint pt = view.point();
  std::vector<double> row = view.probeValues();
  energies_ = view.energies();
  const EnergyTerms& e = energies_;
  for (double x : {e.kinetic, e.strain, e.contact, e.dissipated}) row.push_back(x);
  if (plastic_) row.push_back(e.plastic);
  if (hourglass_) row.push_back(e.hourglass);
  row.push_back(e.total());
  row.push_back(balance_.update(pt.time, e.total() - e.shadow, e.dissipated, e.external));
  if (hourglass_) hourglassMonitor_.update(pt.time, e.hourglass, e.strain + e.plastic, balance_.endReference());
  if (const InteractionOutput* io = view.interactions()) {
    const std::vector<double> v = io->historyValues();
    row.insert(row.end(), v.begin(), v.end());
  }
  for (size_t k = 0; k < row.size(); ++k)  // never a non-finite value in an output
    if (!std::isfinite(row[k]))
      throw NumericalError(format("%s: the solution is not finite at t = %.6e s (%s = %g; unstable time step?)",
                                  what_.c_str(), pt.time, columns_[k].c_str(), row[k]));
  history_.times.push_back(pt.time);
  for (size_t k = 0; k < columns_.size(); ++k) history_.columns[columns_[k]].push_back(row[k]);
  if (csv_ && pending_.empty()) {
    try {
      csv_->appendRow(pt.time, row);
    } catch (const OutputError& e) {
      // One rank writes the file: on several, the others learn of it at the next state the
      // checkpoint observer agrees on (pendingFailure), instead of waiting for this rank.
      if (single_) throw;
      pending_ = e.what();
    }
  }
}

void HistoryObserver::summarize(RunSummary& s) const {
  const EnergyBalanceMonitor::State e = balance_.state();
  s.set("energy/initial", e.e0);
  s.set("energy/reference", balance_.endReference());
  s.set("energy/balance_min", e.first ? 0.0 : e.lowest);
  s.set("energy/balance_max", e.first ? 0.0 : e.highest);
  s.set("energy/balance_max_time", e.highestTime);
  s.set("energy/check", balance_.failed() ? "failed" : balance_.warned() ? "warned" : "ok");
  s.set("recorded_states", static_cast<long long>(history_.times.size()));
  // "<pair>:number of impacts" ... -> impacts.<pair>.number_of_impacts
  for (const auto& [key, value] : history_.statistics) {
    const std::size_t colon = key.find(':');
    if (colon == std::string::npos || key.find(":impact ") != std::string::npos) continue;
    std::string q = key.substr(colon + 1);
    std::replace(q.begin(), q.end(), ' ', '_');
    s.set("impacts/" + key.substr(0, colon) + "/" + q, value);
  }
}

void HistoryObserver::end(bool ok) {
  if (csv_ && ok) csv_->finish();
  if (csv_ && !ok) csv_->abandon();
  if (ok) log() << balance_.summary();
}

}  // namespace choc
