#include "analysis/HistoryChecks.hpp"

#include <cmath>
#include <cstdio>

#include "input/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "output/Log.hpp"
#include "reference/BarImpactExact.hpp"
#include "reference/HistoryError.hpp"

namespace choc {

void declareChecks(Teuchos::ParameterList& p) {
  ParameterList& c = declareNamedSublists(p, "Checks",
                                          "values of the history checked against references");
  declareRequiredString(c, "Quantity", "history column, e.g. 'A:DX'");
  declareRequiredDouble(c, "Time", "time of the check [s]", Range::nonNegative());
  declareRequiredDouble(c, "Reference", "reference value");
  declareChoice(c, "Criterion", "relative", {"relative", "absolute"},
                "relative: |computed-reference|/|reference|; absolute: |computed-reference|");
  declareRequiredDouble(c, "Tolerance", "largest accepted error (a fraction when relative)",
                        Range::positive());
  declareChoice(c, "Kind", "analytic", {"analytic", "exact", "regression"},
                "where the reference comes from");
  declareString(c, "Note", "", "remark printed with the row (e.g. a known inconsistency)");

  ParameterList& e = declareSublist(p, "Exact Solution",
                                    "comparison of the history with the d'Alembert solution of "
                                    "the two-bar impact (BRIEF section 1)");
  declareBool(e, "Enabled", false, "compare the history with the exact solution");
  declareString(e, "Node Set", "A", "node set of point A (its first node)");
  declareChoice(e, "Component", "DX", {"DX", "DY", "DZ"}, "the bar axis");
  declareChoice(e, "Wave Speed", "bar", {"bar", "oedometric", "given"},
                "bar: sqrt(E/rho); oedometric: lateral motion blocked; given: 'Given Wave Speed'. "
                "E, nu, rho are those of the block holding the node");
  declareDouble(e, "Given Wave Speed", 0.0, "c [m/s] when Wave Speed = given", Range::nonNegative());
  declareDouble(e, "Length", 1.0, "length L of each bar [m]", Range::positive());
  declareDouble(e, "Section Area", 4e-4, "section S of the bars [m^2]", Range::positive());
  declareDouble(e, "Impact Velocity", -1.0, "initial velocity v0 of bar AB [m/s]");
  declareDouble(e, "Contact Start", 0.0, "time t0 at which contact starts [s]", Range::nonNegative());
  declareBool(e, "Bilateral", false, "bars tied from t = 0 (modelisation B)");
  declareString(e, "Force Column", "", "history column of the contact force to compare, if any");
  declareDouble(e, "Max Error Tolerance", 0.0,
                "check max |u - u_exact| / peak |u_exact| over the history against this "
                "(0: report only)",
                Range::nonNegative());
  declareDouble(e, "RMS Error Tolerance", 0.0,
                "check the RMS error / peak against this (0: report only)", Range::nonNegative());
}

void verifyChecks(const Teuchos::ParameterList& p, const std::vector<std::string>& columns,
                  double endTime, const std::string& file, const std::string& path) {
  const ParameterList& c = p.sublist("Checks");
  for (auto it = c.begin(); it != c.end(); ++it) {
    const ParameterList& row = c.sublist(c.name(it));
    const std::string q = row.get<std::string>("Quantity");
    bool found = false;
    std::string all;
    for (const auto& col : columns) {
      found = found || col == q;
      all += (all.empty() ? "" : " ") + col;
    }
    if (!found)
      throwInput(file, path + "/Checks/" + c.name(it) + "/Quantity", q, "not a recorded history column",
                 "add it to 'History' (recorded: " + all + ")");
    const double t = row.get<double>("Time");
    if (t > endTime * (1 + 1e-12))
      throwInput(file, path + "/Checks/" + c.name(it) + "/Time", std::to_string(t),
                 "after the end of the run", "the run ends at " + std::to_string(endTime));
  }
}

std::vector<CheckResult> evaluateDeclaredChecks(const Teuchos::ParameterList& p,
                                                const RecordedHistory& h,
                                                const std::string& analysis) {
  std::vector<CheckResult> out;
  const ParameterList& c = p.sublist("Checks");
  for (auto it = c.begin(); it != c.end(); ++it) {
    const ParameterList& row = c.sublist(c.name(it));
    CheckSpec s;
    s.name = c.name(it);
    s.analysis = analysis;
    s.quantity = row.get<std::string>("Quantity");
    s.time = row.get<double>("Time");
    s.reference = row.get<double>("Reference");
    s.criterion = *parseCriterion(row.get<std::string>("Criterion"));
    s.kind = *parseReferenceKind(row.get<std::string>("Kind"));
    s.tolerance = row.get<double>("Tolerance");
    s.note = row.get<std::string>("Note");
    out.push_back(evaluateCheck(s, valueAtTime(h.times, h.columns.at(s.quantity), s.time)));
  }
  return out;
}

namespace {

int blockOfNode(const Mesh& mesh, int node) {
  for (size_t b = 0; b < mesh.blocks.size(); ++b)
    for (int n : mesh.blocks[b].connectivity)
      if (n == node) return static_cast<int>(b);
  return 0;
}

CheckResult exactRow(const std::string& analysis, const std::string& quantity, double time,
                     double computed, double tol, const std::string& note) {
  CheckSpec s;
  s.analysis = analysis;
  s.quantity = quantity;
  s.time = time;
  s.reference = 0.0;
  s.kind = ReferenceKind::Exact;
  s.criterion = Criterion::Absolute;
  s.tolerance = tol;
  s.note = note;
  return evaluateCheck(s, computed);
}

}  // namespace

std::vector<CheckResult> compareWithExact(const Teuchos::ParameterList& p, const RecordedHistory& h,
                                          const Model& model, const std::string& analysis,
                                          const std::string& path) {
  std::vector<CheckResult> out;
  const ParameterList& e = p.sublist("Exact Solution");
  if (!e.get<bool>("Enabled")) return out;
  const std::string file = model.inputFile();
  const std::string set = e.get<std::string>("Node Set");
  const std::string comp = e.get<std::string>("Component");
  const std::string ucol = set + ":" + comp, vcol = set + ":V" + comp.substr(1);
  if (!h.columns.count(ucol))
    throwInput(file, path + "/Exact Solution/Node Set", set,
               "the history does not record '" + ucol + "'", "add '" + ucol + "' to 'History'");
  const NodeSet& ns = model.nodeSet(set, path + "/Exact Solution/Node Set");
  const Material& m = model.materialOfBlock(blockOfNode(model.mesh(), ns.nodes.front()));
  BarImpactParameters bp;
  const std::string ws = e.get<std::string>("Wave Speed");
  bp.waveSpeed = ws == "bar"          ? BarImpactExact::barWaveSpeed(m.youngsModulus, m.density)
                 : ws == "oedometric" ? BarImpactExact::oedometricWaveSpeed(
                                            m.youngsModulus, m.poissonsRatio, m.density)
                                      : e.get<double>("Given Wave Speed");
  bp.length = e.get<double>("Length");
  bp.impedance = m.density * bp.waveSpeed * e.get<double>("Section Area");
  bp.impactVelocity = e.get<double>("Impact Velocity");
  bp.contactStart = e.get<double>("Contact Start");
  bp.bilateral = e.get<bool>("Bilateral");
  BarImpactExact exact(bp);

  auto report = [&](const char* what, const std::string& col, const HistoryError& err) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "  exact solution, %-10s: max error %.3e (%.4f%% of peak %.4e at t = %.4e s), "
                  "RMS %.4f%% of peak\n",
                  col.c_str(), err.maxAbs, 100 * err.maxRelPeak, err.peak, err.timeOfMax,
                  100 * err.rmsRelPeak);
    log() << line;
    (void)what;
  };
  const HistoryError ue = historyError(h.times, h.columns.at(ucol),
                                       [&](double t) { return exact.displacementA(t); });
  report("displacement", ucol, ue);
  const double maxTol = e.get<double>("Max Error Tolerance");
  const double rmsTol = e.get<double>("RMS Error Tolerance");
  if (maxTol > 0)
    out.push_back(exactRow(analysis, ucol + " max error/peak", ue.timeOfMax, ue.maxRelPeak, maxTol,
                           "whole history against the d'Alembert solution"));
  if (rmsTol > 0)
    out.push_back(exactRow(analysis, ucol + " RMS error/peak", h.times.back(), ue.rmsRelPeak, rmsTol,
                           "whole history against the d'Alembert solution"));
  if (h.columns.count(vcol))
    report("velocity", vcol, historyError(h.times, h.columns.at(vcol),
                                          [&](double t) { return exact.velocityA(t); }));
  const std::string fcol = e.get<std::string>("Force Column");
  if (!fcol.empty()) {
    if (!h.columns.count(fcol))
      throwInput(file, path + "/Exact Solution/Force Column", fcol, "not a history column");
    report("force", fcol, historyError(h.times, h.columns.at(fcol),
                                       [&](double t) { return exact.contactForce(t); }));
  }
  return out;
}

}  // namespace choc
