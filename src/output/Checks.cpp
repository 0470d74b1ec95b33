#include "output/Checks.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/Errors.hpp"
#include "core/Files.hpp"
#include "output/HistoryCsv.hpp"

namespace choc {
namespace {

// The shortest "%.Ng" (N = 1..17) that reads back to the same double.
std::string shortestNumber(double v) {
  if (!std::isfinite(v)) return csvNumber(v);
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string printf1(const char* fmt, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string showError(Criterion c, double e) {
  if (!std::isfinite(e)) return printf1("%g", e);
  return c == Criterion::Relative ? printf1("%.3g%%", 100.0 * e) : printf1("%.3g", e);
}

void appendNote(std::string& note, const std::string& more) {
  note += note.empty() ? more : "; " + more;
}

}  // namespace

const char* toString(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::Analytic: return "analytic";
    case ReferenceKind::Exact: return "exact";
    case ReferenceKind::Regression: return "regression";
  }
  return "?";
}

const char* toString(Criterion criterion) {
  return criterion == Criterion::Relative ? "relative" : "absolute";
}

std::optional<ReferenceKind> parseReferenceKind(const std::string& text) {
  for (auto k : {ReferenceKind::Analytic, ReferenceKind::Exact, ReferenceKind::Regression})
    if (text == toString(k)) return k;
  return std::nullopt;
}

std::optional<Criterion> parseCriterion(const std::string& text) {
  for (auto c : {Criterion::Relative, Criterion::Absolute})
    if (text == toString(c)) return c;
  return std::nullopt;
}

CheckResult evaluateCheck(const CheckSpec& spec, double computed) {
  const std::string what = "check " + spec.analysis + " " + spec.quantity;
  if (!std::isfinite(spec.reference))
    throw std::invalid_argument(what + ": reference is not finite");
  if (!std::isfinite(spec.time)) throw std::invalid_argument(what + ": time is not finite");
  if (!std::isfinite(spec.tolerance) || spec.tolerance < 0.0)
    throw std::invalid_argument(what + ": tolerance must be a finite number >= 0");

  CheckResult r;
  r.spec = spec;
  r.computed = computed;
  if (!std::isfinite(computed)) {
    r.error = std::numeric_limits<double>::infinity();
    r.ok = false;
    appendNote(r.spec.note, "computed value is not finite");
    return r;
  }
  const double diff = std::abs(computed - spec.reference);
  if (spec.criterion == Criterion::Relative && spec.reference == 0.0) {
    r.spec.criterion = Criterion::Absolute;
    appendNote(r.spec.note, "reference is 0: absolute error used instead of relative");
    r.error = diff;
  } else if (spec.criterion == Criterion::Relative) {
    r.error = diff / std::abs(spec.reference);
  } else {
    r.error = diff;
  }
  r.ok = r.error <= spec.tolerance;
  return r;
}

bool allPassed(const std::vector<CheckResult>& results) {
  return std::all_of(results.begin(), results.end(), [](const CheckResult& r) { return r.ok; });
}

double valueAtTime(const std::vector<double>& times, const std::vector<double>& values, double t) {
  const std::size_t n = times.size();
  if (values.size() != n)
    throw std::invalid_argument("valueAtTime: " + std::to_string(n) + " times but " +
                                std::to_string(values.size()) + " values");
  if (n == 0) throw std::out_of_range("valueAtTime: no sample");
  if (!std::isfinite(t)) throw std::invalid_argument("valueAtTime: time is not finite");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(times[i]) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("valueAtTime: times are not finite and strictly increasing "
                                  "(sample " + std::to_string(i) + ")");
  const auto outside = [&] {
    return std::out_of_range("valueAtTime: time " + csvNumber(t) + " is outside the samples [" +
                             csvNumber(times.front()) + ", " + csvNumber(times.back()) + "]");
  };
  if (n == 1) {
    if (t == times[0]) return values[0];
    throw outside();
  }
  const std::size_t i = std::lower_bound(times.begin(), times.end(), t) - times.begin();
  if (i == n) {  // beyond the last sample: only a rounding-level miss is accepted
    if (t - times[n - 1] <= 1e-9 * (times[n - 1] - times[n - 2])) return values[n - 1];
    throw outside();
  }
  if (i == 0) {
    if (times[0] - t <= 1e-9 * (times[1] - times[0])) return values[0];
    throw outside();
  }
  const double h = times[i] - times[i - 1];
  if (times[i] - t <= 1e-9 * h) return values[i];
  if (t - times[i - 1] <= 1e-9 * h) return values[i - 1];
  const double w = (t - times[i - 1]) / h;
  return values[i - 1] + w * (values[i] - values[i - 1]);
}

const char* checksCsvHeader() {
  return "analysis,quantity,time,computed,reference,reference_kind,criterion,tolerance,error,"
         "status,note";
}

std::string checkCsvRow(const CheckResult& r) {
  const CheckSpec& s = r.spec;
  return csvField(s.analysis) + "," + csvField(s.quantity) + "," + shortestNumber(s.time) + "," +
         shortestNumber(r.computed) + "," + shortestNumber(s.reference) + "," + toString(s.kind) +
         "," + toString(s.criterion) + "," + shortestNumber(s.tolerance) + "," +
         shortestNumber(r.error) + "," + (r.ok ? "OK" : "NOOK") + "," + csvField(s.note);
}

void writeChecksCsv(const std::string& path, const std::vector<CheckResult>& results) {
  std::string text = std::string(checksCsvHeader()) + "\n";
  for (const auto& r : results) text += checkCsvRow(r) + "\n";
  writeWholeFile(path, text, true, incompletePath(path));
}

std::string formatCheckTable(const std::vector<CheckResult>& results) {
  const std::vector<std::string> head = {"analysis", "quantity", "time", "computed", "reference",
                                         "kind", "error", "tolerance", "status", "note"};
  std::vector<std::vector<std::string>> cells;
  std::size_t nook = 0;
  for (const auto& r : results) {
    const CheckSpec& s = r.spec;
    nook += r.ok ? 0 : 1;
    cells.push_back({s.analysis, s.quantity, printf1("%g", s.time), printf1("%.6g", r.computed),
                     printf1("%.6g", s.reference), toString(s.kind),
                     showError(s.criterion, r.error), showError(s.criterion, s.tolerance),
                     r.ok ? "OK" : "NOOK", s.note});
  }
  std::vector<std::size_t> width(head.size());
  for (std::size_t j = 0; j < head.size(); ++j) {
    width[j] = head[j].size();
    for (const auto& row : cells) width[j] = std::max(width[j], row[j].size());
  }
  const auto line = [&](const std::vector<std::string>& row) {
    std::string out;
    for (std::size_t j = 0; j < row.size(); ++j) {
      const bool last = j + 1 == row.size();
      out += row[j];
      if (!last) out += std::string(width[j] - row[j].size() + 2, ' ');
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  std::string out = line(head);
  for (const auto& row : cells) out += line(row);
  out += std::to_string(results.size()) + " checks, " + std::to_string(nook) + " NOOK\n";
  return out;
}

}  // namespace choc
