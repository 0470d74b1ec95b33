// Check 'Value': a history column at a time against a reference value with a relative or
// absolute tolerance (the document's table rows).
#pragma once
#include "checks/HistoryCheck.hpp"

namespace choc {

class ValueCheck : public HistoryCheck {
 public:
  static Teuchos::ParameterList parameters();
  static std::unique_ptr<HistoryCheck> create(const Teuchos::ParameterList& row, const Model& model,
                                              const CheckSite& site);
  void verify(const std::vector<std::string>& columns, double endTime) const override;
  std::vector<CheckResult> evaluate(const RecordedHistory& h) const override;

 private:
  CheckSpec spec_;
  CheckSite site_;
};

}  // namespace choc
