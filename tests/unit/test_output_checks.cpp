#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "output/Checks.hpp"
#include "output/HistoryCsv.hpp"

namespace fs = std::filesystem;

namespace {

choc::CheckSpec spec(double reference, choc::Criterion c, double tolerance) {
  choc::CheckSpec s;
  s.analysis = "run1";
  s.quantity = "A:DX";
  s.time = 4e-4;
  s.reference = reference;
  s.kind = choc::ReferenceKind::Analytic;
  s.criterion = c;
  s.tolerance = tolerance;
  return s;
}

TEST(Checks, RelativeCriterion) {
  const auto r = choc::evaluateCheck(spec(-2e-4, choc::Criterion::Relative, 0.035), -1.95e-4);
  EXPECT_NEAR(r.error, 0.025, 1e-12);
  EXPECT_TRUE(r.ok);
  const auto n = choc::evaluateCheck(spec(-2e-4, choc::Criterion::Relative, 0.02), -1.95e-4);
  EXPECT_FALSE(n.ok);
  EXPECT_EQ(n.spec.criterion, choc::Criterion::Relative);
  EXPECT_TRUE(n.spec.note.empty());
  // error == tolerance passes.
  EXPECT_TRUE(choc::evaluateCheck(spec(-4.0, choc::Criterion::Relative, 0.25), -5.0).ok);
}

TEST(Checks, AbsoluteCriterion) {
  // The exact solution's value at 8e-4 s for c = sqrt(E/rho) against A's absolute row.
  const auto r = choc::evaluateCheck(spec(-1e-9, choc::Criterion::Absolute, 1e-5), 1.0063e-5);
  EXPECT_NEAR(r.error, 1.0064e-5, 1e-18);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(choc::evaluateCheck(spec(-1e-9, choc::Criterion::Absolute, 1e-5), 5e-6).ok);
}

TEST(Checks, ZeroReferenceFallsBackToAbsoluteAndSaysSo) {
  auto s = spec(0.0, choc::Criterion::Relative, 1e-5);
  s.note = "row 4";
  const auto r = choc::evaluateCheck(s, 3e-6);
  EXPECT_DOUBLE_EQ(r.error, 3e-6);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.spec.criterion, choc::Criterion::Absolute);
  EXPECT_NE(r.spec.note.find("row 4"), std::string::npos);
  EXPECT_NE(r.spec.note.find("absolute"), std::string::npos);
}

TEST(Checks, NonFiniteComputedIsNook) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(),
                     std::numeric_limits<double>::infinity()}) {
    const auto r = choc::evaluateCheck(spec(1.0, choc::Criterion::Absolute, 1e300), bad);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(std::isinf(r.error));
    EXPECT_NE(r.spec.note.find("not finite"), std::string::npos);
  }
  EXPECT_THROW(choc::evaluateCheck(spec(1.0, choc::Criterion::Absolute, -1.0), 1.0),
               std::invalid_argument);
  EXPECT_THROW(choc::evaluateCheck(spec(NAN, choc::Criterion::Absolute, 1.0), 1.0),
               std::invalid_argument);
}

TEST(Checks, EnumSpellings) {
  EXPECT_STREQ(choc::toString(choc::ReferenceKind::Analytic), "analytic");
  EXPECT_STREQ(choc::toString(choc::ReferenceKind::Exact), "exact");
  EXPECT_STREQ(choc::toString(choc::ReferenceKind::Regression), "regression");
  EXPECT_STREQ(choc::toString(choc::Criterion::Relative), "relative");
  EXPECT_EQ(choc::parseReferenceKind("exact"), choc::ReferenceKind::Exact);
  EXPECT_FALSE(choc::parseReferenceKind("ANALYTIQUE").has_value());
  EXPECT_EQ(choc::parseCriterion("absolute"), choc::Criterion::Absolute);
  EXPECT_FALSE(choc::parseCriterion("rel").has_value());
}

TEST(Checks, ValueAtTimeInterpolatesAndHitsSamples) {
  std::vector<double> t, v;
  double s = 0.0;
  for (int i = 0; i <= 1020; ++i) {  // accumulated times drift from i * 1e-6
    t.push_back(s);
    v.push_back(static_cast<double>(i) * i);
    s += 1e-6;
  }
  ASSERT_NE(t[200], 2e-4);  // the drift this guards against
  EXPECT_EQ(choc::valueAtTime(t, v, 2e-4), 40000.0);
  EXPECT_EQ(choc::valueAtTime(t, v, 1.02e-3), 1020.0 * 1020.0);  // last sample, rounding miss
  EXPECT_EQ(choc::valueAtTime(t, v, 0.0), 0.0);
  EXPECT_NEAR(choc::valueAtTime(t, v, 0.5 * (t[10] + t[11])), 0.5 * (100 + 121), 1e-9);
  EXPECT_NEAR(choc::valueAtTime(t, v, t[10] + 0.25 * (t[11] - t[10])), 100 + 0.25 * 21, 1e-9);
  EXPECT_THROW(choc::valueAtTime(t, v, -1e-7), std::out_of_range);
  EXPECT_THROW(choc::valueAtTime(t, v, 1.021e-3), std::out_of_range);
  EXPECT_THROW(choc::valueAtTime({0, 1, 1}, {0, 1, 2}, 0.5), std::invalid_argument);
  EXPECT_THROW(choc::valueAtTime({0, 1}, {0}, 0.5), std::invalid_argument);
  EXPECT_THROW(choc::valueAtTime({}, {}, 0.0), std::out_of_range);
  EXPECT_EQ(choc::valueAtTime({3.0}, {7.0}, 3.0), 7.0);
}

TEST(Checks, ChecksCsvHeaderRowsAndNaming) {
  const fs::path d = fs::path(CHOC_BINARY_DIR) / "test_output_tmp" / "checks_csv";
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string path = (d / "checks.csv").string();
  auto a = spec(-2e-4, choc::Criterion::Relative, 0.035);
  auto b = spec(-1.55e-4, choc::Criterion::Relative, 3e-4);
  b.analysis = "e";
  b.quantity = "N1:DZ";
  b.note = "known inconsistency: exact value is 0.27% away, see docs/verification/sdnl111e.md";
  choc::writeChecksCsv(path, {choc::evaluateCheck(a, -1.9496835316262998e-4),
                              choc::evaluateCheck(b, -1.5541990876814815e-4)});
  EXPECT_FALSE(fs::exists(path + ".part"));
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "analysis,quantity,time,computed,reference,reference_kind,criterion,tolerance,error,"
            "status,note");
  const auto r1 = choc::splitCsvLine(lines[1]);
  ASSERT_EQ(r1.size(), 11u);
  EXPECT_EQ(r1[0], "run1");
  EXPECT_EQ(r1[1], "A:DX");
  EXPECT_EQ(r1[2], "0.0004");
  EXPECT_EQ(std::stod(r1[3]), -1.9496835316262998e-4);  // exact round trip
  EXPECT_EQ(r1[4], "-0.0002");
  EXPECT_EQ(r1[5], "analytic");
  EXPECT_EQ(r1[6], "relative");
  EXPECT_EQ(r1[7], "0.035");
  EXPECT_NEAR(std::stod(r1[8]), 0.0251582341868, 1e-12);
  EXPECT_EQ(r1[9], "OK");
  EXPECT_EQ(r1[10], "");
  const auto r2 = choc::splitCsvLine(lines[2]);
  ASSERT_EQ(r2.size(), 11u);
  EXPECT_EQ(r2[9], "NOOK");
  EXPECT_EQ(r2[10], b.note);

  // A file that cannot be written leaves no file under the final name: its .part name is a
  // directory here.
  fs::remove(path);
  fs::create_directories(path + ".part");
  EXPECT_THROW(choc::writeChecksCsv(path, {}), choc::OutputError);
  EXPECT_FALSE(fs::exists(path));
}

TEST(Checks, FormatCheckTable) {
  const auto ok = choc::evaluateCheck(spec(-2e-4, choc::Criterion::Relative, 0.035), -1.95e-4);
  const auto bad = choc::evaluateCheck(spec(-1e-9, choc::Criterion::Absolute, 1e-5), 1.0063e-5);
  const std::string t = choc::formatCheckTable({ok, bad});
  EXPECT_NE(t.find("2.5%"), std::string::npos) << t;
  EXPECT_NE(t.find("3.5%"), std::string::npos) << t;
  EXPECT_NE(t.find("1.01e-05"), std::string::npos) << t;
  EXPECT_NE(t.find("2 checks, 1 NOOK"), std::string::npos) << t;
  // Aligned: the status column starts at the same offset on every line.
  std::vector<std::string> lines;
  for (std::size_t p = 0, q; (q = t.find('\n', p)) != std::string::npos; p = q + 1)
    lines.push_back(t.substr(p, q - p));
  ASSERT_EQ(lines.size(), 4u);
  const auto col = lines[0].find("status");
  EXPECT_EQ(lines[1].substr(col, 2), "OK");
  EXPECT_EQ(lines[2].substr(col, 4), "NOOK");
  EXPECT_FALSE(choc::allPassed({ok, bad}));
  EXPECT_TRUE(choc::allPassed({ok}));
}

}  // namespace
