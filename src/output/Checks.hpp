// Declared checks (docs/user-guide/checks.md): evaluation against a reference value,
// checks.csv, and the table printed in the run log.
#pragma once
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace choc {

enum class ReferenceKind { Analytic, Exact, Regression };  // "analytic", "exact", "regression"
enum class Criterion { Relative, Absolute };               // "relative", "absolute"

const char* toString(ReferenceKind kind);
const char* toString(Criterion criterion);
std::optional<ReferenceKind> parseReferenceKind(const std::string& text);  // exact spelling
std::optional<Criterion> parseCriterion(const std::string& text);

struct CheckSpec {
  std::string name;      // optional label (not written to checks.csv)
  std::string analysis;  // e.g. "run1"
  std::string quantity;  // history column, e.g. "A:DX"
  double time = 0.0;
  double reference = 0.0;
  ReferenceKind kind = ReferenceKind::Analytic;
  Criterion criterion = Criterion::Relative;
  double tolerance = 0.0;  // a fraction when relative (0.035 = 3.5 %), in the unit otherwise
  std::string note;        // e.g. "known inconsistency: ..."
};

struct CheckResult {
  CheckSpec spec;  // as evaluated: criterion Absolute when a relative check had reference 0
  double computed = 0.0;
  double error = 0.0;  // +infinity when computed is not finite
  bool ok = false;
};

// relative: |c - r| / |r| (r == 0: |c - r|, criterion switched to absolute, said in the note);
// absolute: |c - r|. ok = error <= tolerance; a non-finite computed value is NOOK.
// Throws std::invalid_argument if the reference, time or tolerance is not finite or the
// tolerance is negative.
CheckResult evaluateCheck(const CheckSpec& spec, double computed);

bool allPassed(const std::vector<CheckResult>& results);

// Linear interpolation between the samples bracketing t; the sample itself when
// |t_i - t| <= 1e-9 * (local spacing). times must be strictly increasing
// (std::invalid_argument); t outside [t_0, t_n] throws std::out_of_range.
double valueAtTime(const std::vector<double>& times, const std::vector<double>& values, double t);

// checks.csv, one row per check, across all the analyses of one run: written whole to
// "<path>.part" and renamed to <path>. Throws OutputError naming the file when it cannot be
// written (no file then bears the final name).
const char* checksCsvHeader();  // analysis,...,status,note
void writeChecksCsv(const std::string& path, const std::vector<CheckResult>& results);

// One row of checks.csv (no newline). Numbers in the shortest form that reads back exactly.
std::string checkCsvRow(const CheckResult& r);

// Aligned table for the run log: one line per check, then "N checks, M NOOK".
std::string formatCheckTable(const std::vector<CheckResult>& results);

}  // namespace choc
