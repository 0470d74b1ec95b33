#include "checks/BarImpactCheck.hpp"

#include "core/Errors.hpp"
#include "reference/BarImpactExact.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "input/ParameterSpec.hpp"
#include "reference/HistoryError.hpp"

namespace choc {

namespace {

class BarImpactCheck : public HistoryCheck {
 public:
  BarImpactCheck(const Teuchos::ParameterList& row, const Model& model, const CheckSite& site);
  void verify(const std::vector<std::string>& columns, double endTime) const override;
  std::vector<CheckResult> evaluate(const RecordedHistory& h) const override;

 private:
  BarImpactParameters bar_;
  CheckSite site_;
  std::string set_, ucol_, vcol_, fcol_;
  double maxTol_ = 0, rmsTol_ = 0;
};

}  // namespace

Teuchos::ParameterList barImpactCheckParameters() {
  Teuchos::ParameterList e;
  declareRequiredChoice(e, "Type", {"Bar Impact Exact Solution"}, "check type");
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
  declareChoice(e, "Obstacle", "bar", {"bar", "rigid wall"},
                "what the bar hits: an identical bar clamped at its far end (SDNL111) or a rigid "
                "wall (SDNV100)");
  declareChoice(e, "Point", "contact end", {"contact end", "free end"},
                "where the node set lies on the bar (free end: against a rigid wall only)");
  declareString(e, "Force Column", "", "history column of the contact force to compare, if any");
  declareDouble(e, "Max Error Tolerance", 0.0,
                "check max |u - u_exact| / peak |u_exact| over the history against this "
                "(0: report only)",
                Range::nonNegative());
  declareDouble(e, "RMS Error Tolerance", 0.0,
                "check the RMS error / peak against this (0: report only)", Range::nonNegative());
  return e;
}

namespace {

int blockOfNode(const Mesh& mesh, int node) {
  for (size_t b = 0; b < mesh.blocks.size(); ++b)
    for (int n : mesh.blocks[b].connectivity)
      if (n == node) return static_cast<int>(b);
  return 0;
}

CheckResult exactRow(const std::string& analysis, const std::string& quantity, double time,
                     double computed, double tol) {
  CheckSpec s;
  s.analysis = analysis;
  s.quantity = quantity;
  s.time = time;
  s.reference = 0.0;
  s.kind = ReferenceKind::Exact;
  s.criterion = Criterion::Absolute;
  s.tolerance = tol;
  s.note = "whole history against the d'Alembert solution";
  return evaluateCheck(s, computed);
}

void report(const std::string& col, const HistoryError& err) {
  log() << format("  exact solution, %-10s: max error %.3e (%.4f%% of peak %.4e at t = %.4e s), "
                  "RMS %.4f%% of peak\n",
                  col.c_str(), err.maxAbs, 100 * err.maxRelPeak, err.peak, err.timeOfMax,
                  100 * err.rmsRelPeak);
}

}  // namespace

std::unique_ptr<HistoryCheck> makeBarImpactCheck(const Teuchos::ParameterList& row,
                                                 const Model& model, const CheckSite& site) {
  return std::make_unique<BarImpactCheck>(row, model, site);
}

BarImpactCheck::BarImpactCheck(const Teuchos::ParameterList& e, const Model& model,
                               const CheckSite& site)
    : site_(site) {
  set_ = e.get<std::string>("Node Set");
  const std::string comp = e.get<std::string>("Component");
  ucol_ = set_ + ":" + comp;
  vcol_ = set_ + ":V" + comp.substr(1);
  fcol_ = e.get<std::string>("Force Column");
  maxTol_ = e.get<double>("Max Error Tolerance");
  rmsTol_ = e.get<double>("RMS Error Tolerance");
  const NodeSet& ns = model.nodeSet(set_, site.path + "/Node Set");
  const Material& m = model.materialOfBlock(blockOfNode(model.mesh(), ns.nodes.front()));
  BarImpactParameters& bp = bar_;
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
  bp.rigidWall = e.get<std::string>("Obstacle") == "rigid wall";
  bp.freeEnd = e.get<std::string>("Point") == "free end";
  if (bp.freeEnd && !bp.rigidWall)
    throwInput(site.file, site.path + "/Point", "free end", "needs 'Obstacle' = 'rigid wall'",
               "use 'contact end' for the two-bar impact");
  if (bp.rigidWall && bp.bilateral)
    throwInput(site.file, site.path + "/Bilateral", "true", "a rigid wall is unilateral",
               "set 'Bilateral' to false");
}

void BarImpactCheck::verify(const std::vector<std::string>& columns, double) const {
  auto recorded = [&](const std::string& c) {
    for (const auto& x : columns)
      if (x == c) return true;
    return false;
  };
  if (!recorded(ucol_))
    throwInput(site_.file, site_.path + "/Node Set", set_,
               "the history does not record '" + ucol_ + "'", "add '" + ucol_ + "' to 'History'");
  if (!fcol_.empty() && !recorded(fcol_))
    throwInput(site_.file, site_.path + "/Force Column", fcol_, "not a history column");
}

std::vector<CheckResult> BarImpactCheck::evaluate(const RecordedHistory& h) const {
  std::vector<CheckResult> out;
  const BarImpactExact exact(bar_);
  const HistoryError ue = historyError(h.times, h.columns.at(ucol_),
                                       [&](double t) { return exact.displacementA(t); });
  report(ucol_, ue);
  if (maxTol_ > 0)
    out.push_back(exactRow(site_.analysis, ucol_ + " max error/peak", ue.timeOfMax, ue.maxRelPeak, maxTol_));
  if (rmsTol_ > 0)
    out.push_back(exactRow(site_.analysis, ucol_ + " RMS error/peak", h.times.back(), ue.rmsRelPeak, rmsTol_));
  if (h.columns.count(vcol_))
    report(vcol_, historyError(h.times, h.columns.at(vcol_), [&](double t) { return exact.velocityA(t); }));
  if (!fcol_.empty())
    report(fcol_, historyError(h.times, h.columns.at(fcol_), [&](double t) { return exact.contactForce(t); }));
  return out;
}

}  // namespace choc
