// Checks of a transient history: the rows an input declares ('Checks': value at a time
// against a reference with a tolerance) and the comparison of the whole history with the
// exact d'Alembert solution of the bar impact ('Exact Solution').
#pragma once
#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "analysis/Model.hpp"
#include "output/Checks.hpp"

namespace choc {

struct RecordedHistory {
  std::vector<double> times;
  std::map<std::string, std::vector<double>> columns;
};

void declareChecks(Teuchos::ParameterList& analysisParameters);

// Validates references (quantities recorded, times inside the run) before the run starts.
void verifyChecks(const Teuchos::ParameterList& p, const std::vector<std::string>& columns,
                  double endTime, const std::string& file, const std::string& path);

std::vector<CheckResult> evaluateDeclaredChecks(const Teuchos::ParameterList& p,
                                                const RecordedHistory& h,
                                                const std::string& analysis);

// Logs max and RMS errors relative to the peak for displacement (and velocity / force when
// recorded) and returns check rows for the tolerances the input sets.
std::vector<CheckResult> compareWithExact(const Teuchos::ParameterList& p, const RecordedHistory& h,
                                          const Model& model, const std::string& analysis,
                                          const std::string& path);

}  // namespace choc
