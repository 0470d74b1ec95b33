#include "checks/ImpactCheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "observers/ImpactObserver.hpp"

namespace choc {

namespace {

class ImpactCheck : public HistoryCheck {
 public:
  ImpactCheck(const Teuchos::ParameterList& row, const CheckSite& site);
  void verify(const std::vector<std::string>& columns, double endTime) const override;
  std::vector<CheckResult> evaluate(const RecordedHistory& h) const override;

 private:
  CheckSpec spec_;
  CheckSite site_;
  std::string link_, statistic_;
  int impact_ = 0;
};

std::vector<std::string> allQuantities() {
  std::vector<std::string> q = impactQuantities();
  q.insert(q.end(), impactSummaryQuantities().begin(), impactSummaryQuantities().end());
  return q;
}

}  // namespace

Teuchos::ParameterList impactCheckParameters() {
  Teuchos::ParameterList c;
  declareChoice(c, "Type", "Impact", {"Impact"}, "check type");
  declareRequiredString(c, "Link", "name of a shock link of the analysis");
  declareInt(c, "Impact", 0, "impact number (1 = the first); 0 for a quantity of the whole run",
             Range::atLeast(0));
  declareChoice(c, "Quantity", "peak force", allQuantities(),
                "per impact: start time, end time, peak time, peak force, duration, impulse, impact "
                "velocity (d(gap)/dt before the impact), wear work; with Impact = 0: number of "
                "impacts, largest peak force, mean peak force, total impulse, total wear work");
  declareReferenceParameters(c);
  return c;
}

std::unique_ptr<HistoryCheck> makeImpactCheck(const Teuchos::ParameterList& row, const Model&,
                                              const CheckSite& site) {
  return std::make_unique<ImpactCheck>(row, site);
}

ImpactCheck::ImpactCheck(const Teuchos::ParameterList& row, const CheckSite& site) : site_(site) {
  link_ = row.get<std::string>("Link");
  impact_ = row.get<int>("Impact");
  const std::string q = row.get<std::string>("Quantity");
  const auto& per = impactQuantities();
  const bool perImpact = std::find(per.begin(), per.end(), q) != per.end();
  if (perImpact && impact_ == 0)
    throwInput(site.file, site.path + "/Impact", "0", "'" + q + "' is a quantity of one impact",
               "give the impact's number (1 = the first)");
  if (!perImpact && impact_ != 0)
    throwInput(site.file, site.path + "/Impact", std::to_string(impact_),
               "'" + q + "' is a quantity of the whole run", "set 'Impact' to 0");
  statistic_ = link_ + ":" + (impact_ > 0 ? "impact " + std::to_string(impact_) + ":" : "") + q;
  spec_ = referenceSpec(row, site);
  spec_.quantity = statistic_;
}

void ImpactCheck::verify(const std::vector<std::string>& columns, double) const {
  for (const auto& c : columns)
    if (c == link_ + ":force") return;
  throwInput(site_.file, site_.path + "/Link", link_, "no shock link of that name in this analysis",
             "name one of its 'Shock Links'");
}

std::vector<CheckResult> ImpactCheck::evaluate(const RecordedHistory& h) const {
  const auto it = h.statistics.find(statistic_);
  CheckSpec s = spec_;
  if (it == h.statistics.end()) {
    s.note = (s.note.empty() ? "" : s.note + "; ") + "impact " + std::to_string(impact_) + " did not happen";
    return {evaluateCheck(s, std::numeric_limits<double>::quiet_NaN())};
  }
  const auto peak = h.statistics.find(link_ + ":impact " + std::to_string(impact_) + ":peak time");
  if (peak != h.statistics.end()) s.time = peak->second;  // the row's time: the impact's peak
  return {evaluateCheck(s, it->second)};
}

}  // namespace choc
