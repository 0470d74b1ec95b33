// The checks of a transient's history, one entry of the analysis' 'Checks' list each, of a
// kind chosen by its 'Type': 'Value' (a value at a time against a reference, the default) or
// 'Bar Impact Exact Solution' (the whole history against the d'Alembert solution of the
// two-bar impact of SDNL111, docs/verification/benchmarks.md). A check is resolved before the
// run (the columns it reads are recorded, its times inside the run, its node sets in the mesh)
// and evaluated after it into rows of checks.csv.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "input/Validation.hpp"
#include "output/Checks.hpp"
#include "output/RecordedHistory.hpp"
#include "physics/Model.hpp"

namespace choc {

class HistoryCheck {
 public:
  virtual ~HistoryCheck() = default;
  // Throws InputError when a column it reads is not recorded or a time is after endTime.
  virtual void verify(const std::vector<std::string>& columns, double endTime) const = 0;
  virtual std::vector<CheckResult> evaluate(const RecordedHistory& h) const = 0;
};

// Where a check is and what it belongs to, for messages and rows.
struct CheckSite {
  std::string file;      // the input file
  std::string path;      // "Analyses/<analysis>/Checks/<name>"
  std::string analysis;  // "<analysis>"
  std::string name;      // "<name>"
};

struct CheckKind {
  std::string type;
  std::string doc;
  Teuchos::ParameterList (*parameters)();
  std::unique_ptr<HistoryCheck> (*create)(const Teuchos::ParameterList& row, const Model& model,
                                          const CheckSite& site);
};

const std::vector<CheckKind>& checkKinds();

// The parameters every row check against a reference shares: Reference, Criterion, Tolerance,
// Kind, Note; and the spec they give (name and analysis from the site; quantity and time are
// the check's own).
void declareReferenceParameters(Teuchos::ParameterList& row);
CheckSpec referenceSpec(const Teuchos::ParameterList& row, const CheckSite& site);

// Declares the (open) 'Checks' list of an analysis.
void declareChecks(Teuchos::ParameterList& analysis);
// The 'Exact Solution' sublist of earlier releases becomes the check 'exact solution' of type
// 'Bar Impact Exact Solution' at the end of 'Checks' (dropped when not 'Enabled'), with a
// deprecation warning on the log. Called before validation.
void translateDeprecatedExactSolution(Teuchos::ParameterList& analysis, const std::string& file,
                                      const std::string& path);
// Validates each entry of 'Checks' against its Type's parameters ('Value' when absent).
void validateChecks(Teuchos::ParameterList& checks, const InputLocation& where);

// The checks of a validated analysis list, resolved on the model.
std::vector<std::unique_ptr<HistoryCheck>> makeChecks(const Teuchos::ParameterList& analysis,
                                                      const Model& model,
                                                      const std::string& analysisName);

// Appends the rows of every check, in their order in the input.
void evaluateChecks(const std::vector<std::unique_ptr<HistoryCheck>>& checks,
                    const RecordedHistory& history, std::vector<CheckResult>& out);

// Prints the kinds with their parameters (choc parameters).
void printCheckKinds(std::ostream& out, const std::string& indent);

}  // namespace choc
