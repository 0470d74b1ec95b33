#include "checks/HistoryCheck.hpp"

#include "checks/BarImpactCheck.hpp"
#include "checks/ImpactCheck.hpp"
#include "checks/ValueCheck.hpp"
#include "core/DidYouMean.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

const std::vector<CheckKind>& checkKinds() {
  static const std::vector<CheckKind> kinds = {
      {"Value", "a history value at a time against a reference, with a tolerance (the default)",
       &valueCheckParameters, &makeValueCheck},
      {"Bar Impact Exact Solution",
       "the whole history of point A against the d'Alembert solution of the two-bar impact "
       "(SDNL111): max and RMS error relative to the peak",
       &barImpactCheckParameters, &makeBarImpactCheck},
      {"Impact",
       "a statistic of a shock link's impacts (peak force, peak time, duration, impulse, impact "
       "velocity of impact k, or the number of impacts, largest peak force... of the run)",
       &impactCheckParameters, &makeImpactCheck},
  };
  return kinds;
}

void declareReferenceParameters(Teuchos::ParameterList& c) {
  declareRequiredDouble(c, "Reference", "reference value");
  declareChoice(c, "Criterion", "relative", {"relative", "absolute"},
                "relative: |computed-reference|/|reference|; absolute: |computed-reference|");
  declareRequiredDouble(c, "Tolerance", "largest accepted error (a fraction when relative)",
                        Range::positive());
  declareChoice(c, "Kind", "analytic", {"analytic", "exact", "regression"},
                "where the reference comes from");
  declareString(c, "Note", "", "remark printed with the row (e.g. a known inconsistency)");
}

CheckSpec referenceSpec(const Teuchos::ParameterList& row, const CheckSite& site) {
  CheckSpec s;
  s.name = site.name;
  s.analysis = site.analysis;
  s.reference = row.get<double>("Reference");
  s.criterion = *parseCriterion(row.get<std::string>("Criterion"));
  s.kind = *parseReferenceKind(row.get<std::string>("Kind"));
  s.tolerance = row.get<double>("Tolerance");
  s.note = row.get<std::string>("Note");
  return s;
}

void declareChecks(Teuchos::ParameterList& p) {
  declareOpenSublist(p, "Checks",
                     "checks of the history, by name; each has a 'Type' (default 'Value'), see "
                     "'Checks/<name>' below");
}

namespace {

const CheckKind& kindOf(const Teuchos::ParameterList& row, const InputLocation& where) {
  std::vector<std::string> names;
  for (const auto& k : checkKinds()) names.push_back(k.type);
  const std::string type = row.isType<std::string>("Type") ? row.get<std::string>("Type") : "Value";
  for (const auto& k : checkKinds())
    if (k.type == type) return k;
  throwInput(where.file, where.parameter("Type"), type, "unknown check type",
             didYouMean(type, names) + "valid: " + quotedNames(names));
}

}  // namespace

void translateDeprecatedExactSolution(Teuchos::ParameterList& a, const std::string& file,
                                      const std::string& path) {
  if (!a.isSublist("Exact Solution")) return;
  log() << "choc: warning: " << file << ": parameter '" << path
        << "/Exact Solution' is deprecated and will be removed in the next release; write it as "
           "'Checks/<name>' with 'Type' = 'Bar Impact Exact Solution' (without 'Enabled')\n";
  Teuchos::ParameterList old = a.sublist("Exact Solution");
  a.remove("Exact Solution");
  const bool enabled = old.isType<bool>("Enabled") && old.get<bool>("Enabled");
  if (!enabled) return;
  old.remove("Enabled");
  Teuchos::ParameterList& row = a.sublist("Checks").sublist("exact solution");
  row.set("Type", std::string("Bar Impact Exact Solution"));
  row.setParameters(old);
}

void validateChecks(Teuchos::ParameterList& checks, const InputLocation& where) {
  for (auto it = checks.begin(); it != checks.end(); ++it) {
    const std::string name = checks.name(it);
    Teuchos::ParameterList& row = checks.sublist(name);
    const InputLocation at = where.child(name);
    if (row.isParameter("Type") && !row.isType<std::string>("Type"))
      throwInput(at.file, at.parameter("Type"), "", "must be a string", "e.g. type=\"string\"");
    const CheckKind& kind = kindOf(row, at);
    if (!row.isParameter("Type")) row.set("Type", kind.type);
    validate(row, kind.parameters(), at);
  }
}

std::vector<std::unique_ptr<HistoryCheck>> makeChecks(const Teuchos::ParameterList& analysis,
                                                      const Model& model,
                                                      const std::string& analysisName) {
  std::vector<std::unique_ptr<HistoryCheck>> out;
  const Teuchos::ParameterList& checks = analysis.sublist("Checks");
  const std::string base = "Analyses/" + analysisName + "/Checks";
  for (auto it = checks.begin(); it != checks.end(); ++it) {
    const std::string name = checks.name(it);
    const Teuchos::ParameterList& row = checks.sublist(name);
    const CheckSite site{model.inputFile(), base + "/" + name, analysisName, name};
    out.push_back(kindOf(row, {site.file, site.path}).create(row, model, site));
  }
  return out;
}

void evaluateChecks(const std::vector<std::unique_ptr<HistoryCheck>>& checks,
                    const RecordedHistory& history, std::vector<CheckResult>& out) {
  for (const auto& c : checks)
    for (auto& r : c->evaluate(history)) out.push_back(r);
}

void printCheckKinds(std::ostream& out, const std::string& indent) {
  for (const auto& k : checkKinds()) {
    out << indent << "Checks/<name> with Type = '" << k.type << "': " << k.doc << "\n";
    printValidParameters(out, k.parameters(), indent + "  ");
  }
}

}  // namespace choc
