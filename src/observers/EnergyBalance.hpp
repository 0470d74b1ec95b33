// Energy balance of a transient run, shared by the modal and the implicit transients.
//
//   energy:balance(t) = E_total(t) + W_dissipated(t) - E_total(t0) - W_external(t)
//
// E_total = kinetic + strain + contact, W_dissipated the work of the modelled dampers
// (modal or Rayleigh damping, link dashpots), W_external the work of the applied loads. An
// exact integration of the model keeps the balance at zero; what remains is the scheme's own
// (numerical) energy error: negative for schemes dissipative by design (HHT alpha < 0,
// modified average acceleration, generalized-alpha, the dissipation of an impact under
// exactly enforced contact), positive when the scheme adds energy (a step above the stability
// limit, a stiff penalty released in one step, ...).
//
// The analysis warns once, in the log, when the balance leaves the band set by
// 'Energy Balance Tolerance' (relative to the reference energy E_ref = E_total(t0), or the
// largest |W_external| if larger; a run starting at rest without loads uses the largest
// E_total so far) in the direction chosen by 'Energy Balance Warning':
//   growth  (default): balance > +tol E_ref (energy created: the dangerous direction);
//   drift:             |balance| > tol E_ref (also reports the numerical dissipation);
//   off:               never.
// With 'Energy Balance Check' = 'fail' (the default) leaving the band is also a failed check:
// a row "energy:balance / E_ref" in checks.csv and exit 3, so that a run that created energy
// cannot end with exit 0 unnoticed; 'warn' keeps only the warning.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "input/ParameterSpec.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "output/Checks.hpp"
#include "core/Log.hpp"

namespace choc {

inline void declareEnergyBalance(Teuchos::ParameterList& p) {
  declareDouble(p, "Energy Balance Tolerance", 0.05,
                "tolerance of the energy balance E_total(t) + W_dissipated(t) - E_total(0) - "
                "W_external(t) (history column energy:balance), relative to the initial total "
                "energy (or the largest |W_external| if larger); a warning is logged once when "
                "it is exceeded",
                Range::positive());
  declareDouble(p, "Energy Balance Limit", 10.0,
                "the run stops as a numerical failure (exit 2) when the energy balance exceeds "
                "this many times the initial total energy (or the largest |W_external| if "
                "larger): energy created on that scale is an unstable solution, not a result",
                Range::positive());
  declareChoice(p, "Energy Balance Warning", "growth", {"growth", "drift", "off"},
                "growth: warn when the balance exceeds +tol E0 (the scheme created energy); "
                "drift: warn when |balance| exceeds tol E0 (also the numerical dissipation of "
                "HHT, modified average acceleration or generalized-alpha, which makes the "
                "balance negative by design); off: no warning");
  declareChoice(p, "Energy Balance Check", "fail", {"fail", "warn"},
                "fail: a balance outside the band of 'Energy Balance Warning' and 'Energy "
                "Balance Tolerance' is also a failed check (a row in checks.csv, exit 3): a run "
                "that created energy does not end with exit 0; warn: the warning only (for a "
                "scheme known to measure its energy with an error, e.g. central differences "
                "at Courant 1)");
}

struct EnergyBalanceSettings {
  double tolerance = 0.05;
  double limit = 10.0;
  std::string mode = "growth";  // growth, drift, off
  bool failCheck = true;
  // A warning at the end when the balance rose above this share of the reference energy but
  // stayed within the tolerance (0: none): the implicit schemes' 1e-3, so that a non-dissipative
  // scheme's contact release term is not left unnoticed (docs/verification/copper-bar.md).
  double createdNotice = 0.0;
};

inline EnergyBalanceSettings readEnergyBalance(const Teuchos::ParameterList& p) {
  return {p.get<double>("Energy Balance Tolerance"), p.get<double>("Energy Balance Limit"),
          p.get<std::string>("Energy Balance Warning"), p.get<std::string>("Energy Balance Check") == "fail"};
}

class EnergyBalanceMonitor {
 public:
  EnergyBalanceMonitor(const EnergyBalanceSettings& s, std::string what)
      : what_(std::move(what)), tol_(s.tolerance), limit_(s.limit), mode_(s.mode), fail_(s.failCheck),
        notice_(s.createdNotice) {}

  // Called once per recorded state, in time order; the first call fixes E_total(t0).
  // Returns energy:balance.
  double update(double t, double total, double dissipated, double external) {
    if (st_.first) {
      st_.e0 = total;
      st_.first = false;
    }
    st_.maxExternal = std::max(st_.maxExternal, std::abs(external));
    st_.maxTotal = std::max(st_.maxTotal, total);
    const double balance = total + dissipated - st_.e0 - external;
    double ref = std::max(st_.e0, st_.maxExternal);
    if (!(ref > 0)) ref = st_.maxTotal;
    const bool over = mode_ == "growth" ? balance > tol_ * ref
                      : mode_ == "drift" ? std::abs(balance) > tol_ * ref
                                         : false;
    if (over && !st_.warned) {
      st_.warned = true;
      st_.warnedTime = t;
      char b[400];
      std::snprintf(b, sizeof b,
                    "  warning: %s: energy balance %+.4e J at t = %.6e s exceeds %s%.3g x %.4e J "
                    "(%s; 'Energy Balance Tolerance'): %s\n",
                    what_.c_str(), balance, t, mode_ == "growth" ? "+" : "+/-", tol_, ref,
                    st_.e0 > 0 ? "initial total energy" : "reference energy",
                    balance > 0 ? "the scheme creates energy (time step, contact stiffness?)"
                                : "numerical dissipation of the scheme");
      log() << b;
    }
    st_.lowest = std::min(st_.lowest, balance);
    if (balance > st_.highest) st_.highestTime = t;
    st_.highest = std::max(st_.highest, balance);
    const double fixedRef = std::max(st_.e0, st_.maxExternal);  // not the total, which a blow-up grows
    if (fixedRef > 0 && balance > limit_ * fixedRef) {
      char b[400];
      std::snprintf(b, sizeof b,
                    "%s: energy balance %+.4e J at t = %.6e s exceeds %.3g x %.4e J ('Energy "
                    "Balance Limit'): the solution is unstable; lower the time step or add "
                    "numerical damping (with Lagrange or Continuous contact: 'Contact Mass' = "
                    "'redistributed')",
                    what_.c_str(), balance, t, limit_, fixedRef);
      throw NumericalError(b);
    }
    return balance;
  }

  // One summary line for the end of the run.
  std::string summary() const {
    char b[240];
    std::snprintf(b, sizeof b, "  energy balance: E0 = %.6e J, balance in [%+.4e, %+.4e] J%s\n", st_.e0,
                  st_.first ? 0.0 : st_.lowest, st_.first ? 0.0 : st_.highest,
                  failed() ? " (a failed check: 'Energy Balance Check')" : st_.warned ? " (warned)" : "");
    return b + createdWarning();
  }
  // The warning of createdNotice: energy created, less than the tolerance ("" otherwise).
  std::string createdWarning() const {
    const double ref = endReference();
    if (st_.first || !(notice_ > 0) || mode_ == "off" || st_.warned || !(ref > 0) || !(st_.highest > notice_ * ref))
      return "";
    char b[600];
    std::snprintf(b, sizeof b,
                  "  warning: %s: the scheme created energy: the balance reached %+.3g of the reference energy "
                  "at t = %.6e s (above %g, within 'Energy Balance Tolerance' = %g): with contact, the work "
                  "of constraints opening within a step (the release term), which shrinks with the step; a "
                  "smaller step or a dissipative scheme (the default modified average acceleration, HHT) "
                  "keeps it below\n",
                  what_.c_str(), st_.highest / ref, st_.highestTime, notice_, tol_);
    return b;
  }
  bool warned() const { return st_.warned; }

  // With 'Energy Balance Check' = 'fail', a run whose balance left the band is a failed check:
  // the largest balance relative to the reference energy, against the tolerance (at its time).
  // Nothing otherwise (checks.csv holds the declared checks and the failures of this one).
  // Judged at the end against the reference energy of the whole run (with loads, the largest
  // |W_external|): a balance that is large only beside the little work done in the first steps
  // of a ramp (HHT from rest) is not energy created.
  bool failed() const { return fail_ && mode_ != "off" && worst() > tol_ * endReference(); }
  CheckResult checkResult(const std::string& analysis) const {
    CheckSpec spec;
    spec.analysis = analysis;
    const bool growth = mode_ == "growth";
    spec.quantity = growth ? "energy:balance / reference energy, largest" : "|energy:balance| / reference energy, largest";
    spec.time = growth ? st_.highestTime : st_.warnedTime;
    spec.reference = 0.0;
    spec.kind = ReferenceKind::Exact;
    spec.criterion = Criterion::Absolute;
    spec.tolerance = tol_;
    spec.note = "energy created by the scheme beyond 'Energy Balance Tolerance' (first at t = " +
                shortNumber(st_.warnedTime) + " s); 'Energy Balance Check' = warn accepts it";
    const double ref = endReference() > 0 ? endReference() : 1.0;
    return evaluateCheck(spec, worst() / ref);
  }

  double worst() const {
    if (st_.first) return 0.0;
    return mode_ == "growth" ? st_.highest : std::max(st_.highest, -st_.lowest);
  }
  double endReference() const {
    const double ref = std::max(st_.e0, st_.maxExternal);
    return ref > 0 ? ref : st_.maxTotal;
  }

  // What the balance carries from one state to the next (a checkpoint stores it).
  struct State {
    bool first = true, warned = false;
    double e0 = 0.0, maxExternal = 0.0, maxTotal = 0.0;
    double lowest = INFINITY, highest = -INFINITY;
    double highestTime = 0.0, warnedTime = 0.0;
  };
  State state() const { return st_; }
  void setState(const State& s) { st_ = s; }

 private:
  std::string what_;
  double tol_, limit_;
  std::string mode_;
  bool fail_;
  double notice_;
  State st_;
};

}  // namespace choc
