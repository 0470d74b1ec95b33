// Check 'Bar Impact Exact Solution': the history of point A (displacement, and velocity and
// contact force when recorded) against the d'Alembert solution of the two-bar impact
// (BRIEF section 1), with the wave speed and impedance from the material of A's block. Logs
// the max and RMS errors relative to the peak; gives checks.csv rows for the tolerances set.
#pragma once
#include "checks/HistoryCheck.hpp"
#include "reference/BarImpactExact.hpp"

namespace choc {

class BarImpactCheck : public HistoryCheck {
 public:
  static Teuchos::ParameterList parameters();
  static std::unique_ptr<HistoryCheck> create(const Teuchos::ParameterList& row, const Model& model,
                                              const CheckSite& site);
  void verify(const std::vector<std::string>& columns, double endTime) const override;
  std::vector<CheckResult> evaluate(const RecordedHistory& h) const override;

 private:
  BarImpactParameters bar_;
  CheckSite site_;
  std::string set_, ucol_, vcol_, fcol_;
  double maxTol_ = 0, rmsTol_ = 0;
};

}  // namespace choc
