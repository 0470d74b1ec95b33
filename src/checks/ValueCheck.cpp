#include "checks/ValueCheck.hpp"

#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

namespace {

class ValueCheck : public HistoryCheck {
 public:
  ValueCheck(const Teuchos::ParameterList& row, const CheckSite& site);
  void verify(const std::vector<std::string>& columns, double endTime) const override;
  std::vector<CheckResult> evaluate(const RecordedHistory& h) const override;

 private:
  CheckSpec spec_;
  CheckSite site_;
};

}  // namespace

Teuchos::ParameterList valueCheckParameters() {
  Teuchos::ParameterList c;
  declareChoice(c, "Type", "Value", {"Value"}, "check type");
  declareRequiredString(c, "Quantity", "history column, e.g. 'A:DX'");
  declareRequiredDouble(c, "Time", "time of the check [s]", Range::nonNegative());
  declareReferenceParameters(c);
  return c;
}

std::unique_ptr<HistoryCheck> makeValueCheck(const Teuchos::ParameterList& row, const Model&,
                                             const CheckSite& site) {
  return std::make_unique<ValueCheck>(row, site);
}

ValueCheck::ValueCheck(const Teuchos::ParameterList& row, const CheckSite& site) : site_(site) {
  spec_ = referenceSpec(row, site);
  spec_.quantity = row.get<std::string>("Quantity");
  spec_.time = row.get<double>("Time");
}

void ValueCheck::verify(const std::vector<std::string>& columns, double endTime) const {
  bool found = false;
  std::string all;
  for (const auto& col : columns) {
    found = found || col == spec_.quantity;
    all += (all.empty() ? "" : " ") + col;
  }
  if (!found)
    throwInput(site_.file, site_.path + "/Quantity", spec_.quantity, "not a recorded history column",
               "add it to 'History' (recorded: " + all + ")");
  if (spec_.time > endTime * (1 + 1e-12))
    throwInput(site_.file, site_.path + "/Time", std::to_string(spec_.time), "after the end of the run",
               "the run ends at " + std::to_string(endTime));
}

std::vector<CheckResult> ValueCheck::evaluate(const RecordedHistory& h) const {
  return {evaluateCheck(spec_, valueAtTime(h.times, h.columns.at(spec_.quantity), spec_.time))};
}

}  // namespace choc
