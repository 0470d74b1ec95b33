#include "observers/ImpactObserver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "input/ParameterSpec.hpp"
#include "core/Files.hpp"
#include "output/HistoryCsv.hpp"

namespace choc {

void declareImpactStatistics(Teuchos::ParameterList& p) {
  Teuchos::ParameterList& s = declareSublist(
      p, "Impact Statistics", "how impacts are told apart (<analysis>.impacts.csv, 'Impact' checks)");
  declareDouble(s, "Force Threshold", 0.0,
                "an impact lasts while the normal force exceeds this [N] (0: while in contact)",
                Range::nonNegative());
  declareDouble(s, "Minimum Rest Time", 0.0,
                "two contacts separated by less than this [s] count as one impact",
                Range::nonNegative());
}

const std::vector<std::string>& impactQuantities() {
  static const std::vector<std::string> q = {"start time", "end time",        "peak time", "peak force",
                                             "duration",   "impulse",         "impact velocity",
                                             "wear work"};
  return q;
}

const std::vector<std::string>& impactSummaryQuantities() {
  static const std::vector<std::string> q = {"number of impacts", "largest peak force", "mean peak force",
                                             "total impulse", "total wear work"};
  return q;
}

ImpactSettings readImpactSettings(const Teuchos::ParameterList& analysis) {
  const Teuchos::ParameterList& s = analysis.sublist("Impact Statistics");
  return {s.get<double>("Force Threshold"), s.get<double>("Minimum Rest Time")};
}

ImpactObserver::ImpactObserver(std::string csvPath, const ImpactSettings& settings,
                               HistoryObserver& history, const StateArchive* resume)
    : csvPath_(std::move(csvPath)),
      threshold_(settings.forceThreshold),
      rest_(settings.minimumRestTime),
      history_(history) {
  if (!resume || !resume->has("impacts/tracks")) return;
  const auto n = resume->getVector<long long>("impacts/tracks");
  const auto all = resume->getVector<Impact>("impacts/impacts");
  const auto state = resume->getVector<double>("impacts/state");
  const auto flags = resume->getVector<char>("impacts/flags");
  size_t at = 0;
  tracks_.resize(n.size());
  for (size_t i = 0; i < n.size(); ++i) {
    Track& k = tracks_[i];
    k.impacts.assign(all.begin() + at, all.begin() + at + n[i]);
    at += n[i];
    k.active = flags.at(3 * i);
    k.havePrevious = flags.at(3 * i + 1);
    k.rateKnown = flags.at(3 * i + 2);
    const double* x = &state.at(9 * i);
    k.t0 = x[0], k.f0 = x[1], k.g0 = x[2], k.rate0 = x[3], k.p0 = x[4], k.tm = x[5], k.fm = x[6];
    k.largest = x[7];
    k.gapScale = x[8];
  }
}

void ImpactObserver::archive(StateArchive& a) const {
  std::vector<long long> n;
  std::vector<Impact> all;
  std::vector<double> state;
  std::vector<char> flags;
  for (const Track& k : tracks_) {
    n.push_back(static_cast<long long>(k.impacts.size()));
    all.insert(all.end(), k.impacts.begin(), k.impacts.end());
    for (double x : {k.t0, k.f0, k.g0, k.rate0, k.p0, k.tm, k.fm, k.largest, k.gapScale}) state.push_back(x);
    flags.push_back(k.active);
    flags.push_back(k.havePrevious);
    flags.push_back(k.rateKnown);
  }
  a.putVector("impacts/tracks", n);
  a.putVector("impacts/impacts", all);
  a.putVector("impacts/state", state);
  a.putVector("impacts/flags", flags);
}

void ImpactObserver::step(TransientView& view) { sampleAt(view, view.point().time); }

// Every sub-step of an explicit scheme too: the impulse, the peak and the crossings are those
// of every state the scheme computed, not of the step ends only.
void ImpactObserver::substep(TransientView& view, double time) { sampleAt(view, time); }

void ImpactObserver::sampleAt(TransientView& view, double t) {
  const InteractionOutput* io = view.interactions();
  if (!io) return;
  if (names_.empty()) names_ = io->impactNames();
  const std::vector<ImpactSample> s = io->impactSamples();
  tracks_.resize(s.size());
  for (size_t i = 0; i < s.size(); ++i) sample(tracks_[i], t, s[i]);
}

namespace {

// Instant where the linear interpolant from (t0, a0) to (t1, a1) crosses zero.
double crossing(double t0, double a0, double t1, double a1) {
  return a0 == a1 ? t1 : t0 + (t1 - t0) * a0 / (a0 - a1);
}

// Vertex of the parabola through three samples (tm, fm), (t0, f0), (t1, f1), with f0 the
// largest; the sample itself when they are collinear.
void parabolaVertex(double tm, double fm, double t0, double f0, double t1, double f1, double& tp, double& fp) {
  const double d1 = (f0 - fm) / (t0 - tm), d2 = (f1 - f0) / (t1 - t0);
  const double c = (d2 - d1) / (t1 - tm);  // second divided difference
  tp = t0;
  fp = f0;
  if (!(c < 0)) return;
  const double b = d1 - c * (tm + t0);  // f = fm + d1 (t - tm) + c (t - tm)(t - t0)
  const double tv = -b / (2 * c);
  if (tv < tm || tv > t1) return;
  tp = tv;
  fp = fm + d1 * (tv - tm) + c * (tv - tm) * (tv - t0);
}

}  // namespace

void ImpactObserver::sample(Track& k, double t, const ImpactSample& given) {
  ImpactSample s = given;
  bool rateKnown = true;
  if (std::isnan(s.gapRate)) {  // not given (contact pairs): the backward difference of the gap
    rateKnown = k.havePrevious && t > k.t0;
    s.gapRate = rateKnown ? (s.gap - k.g0) / (t - k.t0) : 0.0;
  }
  // Forces below 1e-6 of the largest so far are round-off (a released multiplier of exactly
  // enforced contact), not contact: they would split one impact into several on some ranks.
  const double floor = std::max(threshold_, 1e-6 * k.largest);
  const bool on = s.force > floor;
  k.largest = std::max(k.largest, s.force);
  const double power = s.tangentialForce * s.slipSpeed;
  // The level whose crossing starts or ends an impact (closingTime, openingTime): the gap when
  // the threshold is 0, where gaps within 1e-9 of the largest seen are round-off of a closed
  // contact (0).
  k.gapScale = std::max(k.gapScale, std::abs(s.gap));
  const double tol = 1e-9 * k.gapScale;
  if (k.active)
    continueImpact(k, t, s, on, power, tol);
  else if (on)
    startImpact(k, t, s, power, tol);
  if (k.active) k.impacts.back().end = t;
  remember(k, t, s, power, rateKnown);
}

// The instant the contact closed, between the previous state and the state at t.
double ImpactObserver::closingTime(const Track& k, double t, const ImpactSample& s, double tol) const {
  const bool onGap = threshold_ == 0.0;
  return onGap && k.g0 > tol && s.gap <= tol ? crossing(k.t0, k.g0, t, std::min(s.gap, 0.0))
                                             : crossing(k.t0, k.f0 - threshold_, t, s.force - threshold_);
}

// The instant the contact opened, between the previous state and the state at t.
double ImpactObserver::openingTime(const Track& k, double t, const ImpactSample& s, double tol) const {
  const bool onGap = threshold_ == 0.0;
  return onGap && s.gap > tol && k.g0 <= tol ? crossing(k.t0, std::min(k.g0, 0.0), t, s.gap)
                                             : crossing(k.t0, k.f0 - threshold_, t, s.force - threshold_);
}

// The impact under way: its impulse and wear work up to t (or to its end, when the force no
// longer counts as contact), and its peak.
void ImpactObserver::continueImpact(Track& k, double t, const ImpactSample& s, bool on, double power,
                                    double tol) {
  Impact& im = k.impacts.back();
  if (on) {
    im.impulse += 0.5 * (k.f0 + s.force) * (t - k.t0);
    im.wear += 0.5 * (k.p0 + power) * (t - k.t0);
  } else {
    const double te = openingTime(k, t, s, tol);
    im.impulse += 0.5 * (k.f0 + threshold_) * (te - k.t0);
    im.wear += k.p0 * (te - k.t0);
    im.end = te;
    im.open = false;
    k.active = false;
  }
  // The previous state was the largest so far: refine the peak on the parabola.
  if (k.f0 >= im.peakForce && s.force <= k.f0 && k.havePrevious) {
    double tp, fp;
    parabolaVertex(k.tm, k.fm, k.t0, k.f0, t, s.force, tp, fp);
    if (fp >= im.peakForce) {
      im.peakForce = fp;
      im.peakTime = tp;
    }
  }
  if (on && s.force > im.peakForce) {
    im.peakForce = s.force;
    im.peakTime = t;
  }
}

// A contact begins: a new impact, or the last one again when the rest since it is shorter
// than 'Minimum Rest Time'; its impulse and wear work from where it began to t.
void ImpactObserver::startImpact(Track& k, double t, const ImpactSample& s, double power, double tol) {
  double ts = t, f0 = threshold_;
  if (k.havePrevious) ts = closingTime(k, t, s, tol);
  const bool merge = !k.impacts.empty() && ts - k.impacts.back().end < rest_;
  if (!merge) {
    Impact im;
    im.start = ts;
    // The gap rate before the impact; for a differenced rate from the first state, the
    // secant over the interval where the impact starts.
    im.velocity = !k.havePrevious ? s.gapRate
                  : k.rateKnown ? k.rate0
                                : (s.gap - k.g0) / (t - k.t0);
    k.impacts.push_back(im);
  }
  Impact& im = k.impacts.back();
  im.open = true;
  im.impulse += 0.5 * (f0 + s.force) * (t - ts);
  im.wear += power * (t - ts);
  if (s.force > im.peakForce) {
    im.peakForce = s.force;
    im.peakTime = t;
  }
  k.active = true;
}

// The state at t becomes the previous one.
void ImpactObserver::remember(Track& k, double t, const ImpactSample& s, double power, bool rateKnown) {
  k.tm = k.t0;
  k.fm = k.f0;
  k.t0 = t;
  k.f0 = s.force;
  k.g0 = s.gap;
  k.rate0 = s.gapRate;
  k.p0 = power;
  k.rateKnown = rateKnown;
  k.havePrevious = true;
}

std::map<std::string, double> ImpactObserver::statistics() const {
  std::map<std::string, double> st;
  for (size_t i = 0; i < tracks_.size() && i < names_.size(); ++i) {
    const auto& im = tracks_[i].impacts;
    double largest = 0, sum = 0, impulse = 0, wear = 0;
    for (size_t j = 0; j < im.size(); ++j) {
      const Impact& x = im[j];
      const std::string p = names_[i] + ":impact " + std::to_string(j + 1) + ":";
      const double v[] = {x.start, x.end, x.peakTime, x.peakForce, x.end - x.start, x.impulse, x.velocity, x.wear};
      for (size_t q = 0; q < impactQuantities().size(); ++q) st[p + impactQuantities()[q]] = v[q];
      largest = std::max(largest, x.peakForce);
      sum += x.peakForce;
      impulse += x.impulse;
      wear += x.wear;
    }
    const double v[] = {double(im.size()), largest, im.empty() ? 0.0 : sum / im.size(), impulse, wear};
    for (size_t q = 0; q < impactSummaryQuantities().size(); ++q)
      st[names_[i] + ":" + impactSummaryQuantities()[q]] = v[q];
  }
  return st;
}

void ImpactObserver::write(bool complete) const {
  if (!isRootRank() || names_.empty()) return;
  std::string text =
      "link,impact,start_time,end_time,peak_time,peak_force,duration,impulse,impact_velocity,wear_work,open\n";
  for (size_t i = 0; i < tracks_.size() && i < names_.size(); ++i)
    for (size_t j = 0; j < tracks_[i].impacts.size(); ++j) {
      const Impact& x = tracks_[i].impacts[j];
      text += csvField(names_[i]) + "," + std::to_string(j + 1);
      for (double v : {x.start, x.end, x.peakTime, x.peakForce, x.end - x.start, x.impulse, x.velocity, x.wear})
        text += "," + csvNumber(v);
      text += x.open ? ",1\n" : ",0\n";
    }
  writeWholeFile(csvPath_, text, complete, incompletePath(csvPath_), true);
  // A complete file replaces what an interrupted earlier part of the run left.
  if (complete) removeFile(incompletePath(csvPath_));
}

void ImpactObserver::end(bool ok) {
  if (names_.empty()) return;
  if (!ok) {
    try {
      write(false);
    } catch (...) {
      // The run is already failing; its own error is the one to report.
    }
    return;
  }
  write(true);
  history_.setStatistics(statistics());
  for (size_t i = 0; i < tracks_.size() && i < names_.size(); ++i) {
    const auto& im = tracks_[i].impacts;
    double largest = 0, sum = 0, impulse = 0;
    for (const Impact& x : im) {
      largest = std::max(largest, x.peakForce);
      sum += x.peakForce;
      impulse += x.impulse;
    }
    log() << format("  impacts of '%s': %zu, largest peak force %.6g N, mean %.6g N, total impulse %.6g N s\n",
                    names_[i].c_str(), im.size(), largest, im.empty() ? 0.0 : sum / im.size(), impulse);
  }
}

}  // namespace choc
