#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <iterator>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "output/HistoryCsv.hpp"

namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(CHOC_BINARY_DIR) / "test_output_tmp" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(HistoryCsv, RoundTripIsExact) {
  const fs::path d = freshDir("history_roundtrip");
  const std::string path = (d / "run.history.csv").string();
  const std::vector<double> tricky = {0.1, 1.0 / 3.0, -1.2345678901234567e-300, 5e-324,
                                      1.7976931348623157e308, -0.0, M_PI};
  {
    choc::HistoryCsv h(path, {"A:DX", "energy:total"});
    EXPECT_TRUE(fs::exists(path + ".part"));
    for (std::size_t i = 0; i < tricky.size(); ++i)
      h.appendRow(1e-6 * static_cast<double>(i) + 1e-7, {tricky[i], -tricky[i] / 3.0});
    EXPECT_FALSE(fs::exists(path));
    h.finish();
    EXPECT_EQ(h.rows(), tricky.size());
  }
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  EXPECT_FALSE(fs::exists(d / "run.history.incomplete.csv"));
  EXPECT_EQ(lines(path).at(0), "time,A:DX,energy:total");

  const auto t = choc::readHistoryCsv(path);
  ASSERT_EQ(t.names, (std::vector<std::string>{"time", "A:DX", "energy:total"}));
  ASSERT_EQ(t.rows.size(), tricky.size());
  const auto dx = t.column("A:DX");
  const auto time = t.column("time");
  for (std::size_t i = 0; i < tricky.size(); ++i) {
    EXPECT_EQ(dx[i], tricky[i]) << i;
    EXPECT_EQ(std::signbit(dx[i]), std::signbit(tricky[i])) << i;
    EXPECT_EQ(t.rows[i][t.index("energy:total")], -tricky[i] / 3.0) << i;
    EXPECT_EQ(time[i], 1e-6 * static_cast<double>(i) + 1e-7) << i;
  }
  EXPECT_THROW(t.index("B:DX"), std::out_of_range);
  EXPECT_TRUE(t.has("A:DX"));
  EXPECT_FALSE(t.has("B:DX"));
}

TEST(HistoryCsv, AbandonAndDestructorNameTheFileIncomplete) {
  const fs::path d = freshDir("history_abandon");
  const std::string path = (d / "run.history.csv").string();
  {
    choc::HistoryCsv h(path, {"A:DX"});
    h.appendRow(0.0, {1.0});
    h.abandon();
  }
  EXPECT_TRUE(fs::exists(d / "run.history.incomplete.csv"));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".part"));
  EXPECT_EQ(lines(d / "run.history.incomplete.csv").size(), 2u);

  const std::string other = (d / "b.history.csv").string();
  { choc::HistoryCsv h(other, {"A:DX"}); }  // destroyed unfinished
  EXPECT_TRUE(fs::exists(d / "b.history.incomplete.csv"));
  EXPECT_FALSE(fs::exists(other));

  // A new run removes the stale results of the earlier one.
  { std::ofstream(other) << "stale\n"; }
  choc::HistoryCsv h(other, {"A:DX"});
  EXPECT_FALSE(fs::exists(other));
  EXPECT_FALSE(fs::exists(d / "b.history.incomplete.csv"));
  h.finish();
  EXPECT_EQ(lines(other), (std::vector<std::string>{"time,A:DX"}));
}

TEST(HistoryCsv, IncompletePath) {
  EXPECT_EQ(choc::incompletePath("out/run.history.csv"), "out/run.history.incomplete.csv");
  EXPECT_EQ(choc::incompletePath("checks.csv"), "checks.incomplete.csv");
  EXPECT_EQ(choc::incompletePath("run"), "run.incomplete");
}

TEST(HistoryCsv, NonFiniteValueIsANumericalErrorNamingColumnAndTime) {
  const fs::path d = freshDir("history_nan");
  choc::HistoryCsv h((d / "r.history.csv").string(), {"A:DX", "N1:DZ"});
  h.appendRow(0.0, {0.0, 0.0});
  try {
    h.appendRow(2.5e-4, {1.0, std::numeric_limits<double>::quiet_NaN()});
    FAIL() << "NaN accepted";
  } catch (const choc::NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("N1:DZ"), std::string::npos) << m;
    EXPECT_NE(m.find("0.00025"), std::string::npos) << m;
  }
  EXPECT_THROW(h.appendRow(3e-4, {std::numeric_limits<double>::infinity(), 0.0}),
               choc::NumericalError);
  EXPECT_THROW(h.appendRow(std::numeric_limits<double>::quiet_NaN(), {0.0, 0.0}),
               choc::NumericalError);
  EXPECT_THROW(h.appendRow(3e-4, {0.0}), std::invalid_argument);
  EXPECT_EQ(h.rows(), 1u);  // nothing of the refused rows was written
  h.finish();
  EXPECT_EQ(choc::readHistoryCsv((d / "r.history.csv").string()).rows.size(), 1u);
}

TEST(HistoryCsv, BadColumnNamesAndUnwritableDirectory) {
  const fs::path d = freshDir("history_names");
  const std::string p = (d / "r.history.csv").string();
  EXPECT_THROW(choc::HistoryCsv(p, {"time"}), std::invalid_argument);
  EXPECT_THROW(choc::HistoryCsv(p, {"A:DX", "A:DX"}), std::invalid_argument);
  EXPECT_THROW(choc::HistoryCsv(p, {""}), std::invalid_argument);
  EXPECT_THROW(choc::HistoryCsv(p, {"a,b"}), std::invalid_argument);
  EXPECT_THROW(choc::HistoryCsv((d / "missing" / "r.history.csv").string(), {"A:DX"}),
               choc::OutputError);
}

// A write the disk takes only part of (here a file-size limit: write() stores what fits, then
// fails) leaves the file cut back to its last whole row: every row of the .incomplete file
// parses, and the failure is an OutputError naming the file.
TEST(HistoryCsv, AShortWriteLeavesOnlyWholeRows) {
  const fs::path d = freshDir("history_short_write");
  const std::string p = (d / "r.history.csv").string();
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit small = old;
  small.rlim_cur = 100000;  // bytes: not a multiple of any row's length
  setrlimit(RLIMIT_FSIZE, &small);
  std::string message;
  {
    choc::HistoryCsv h(p, {"A:DX", "energy:total"});
    try {
      for (int i = 0; i < 100000; ++i) h.appendRow(1e-6 * i + 1e-13, {0.1 * i + 1e-7, 1.0 / (i + 3)});
    } catch (const choc::OutputError& e) {
      message = e.what();
    }
  }
  setrlimit(RLIMIT_FSIZE, &old);
  EXPECT_NE(message.find("r.history.csv.part"), std::string::npos) << message;
  const std::string incomplete = (d / "r.history.incomplete.csv").string();
  ASSERT_TRUE(fs::exists(incomplete));
  EXPECT_FALSE(fs::exists(p));
  EXPECT_LE(fs::file_size(incomplete), 100000u);
  std::ifstream in(incomplete, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const auto t = choc::parseHistoryCsv(text, incomplete);  // throws on a partial row
  EXPECT_GE(t.rows.size(), 1000u);  // the rows written before the failing one reached the disk
}

TEST(HistoryCsv, FlushedAtLeastEvery1000Rows) {
  const fs::path d = freshDir("history_flush");
  const std::string p = (d / "r.history.csv").string();
  choc::HistoryCsv h(p, {"A:DX"});
  for (int i = 0; i < 1000; ++i) h.appendRow(1e-6 * i, {0.5 * i});
  EXPECT_GE(lines(p + ".part").size(), 1001u);  // header + 1000 rows on disk, still open
  h.finish();
}

TEST(HistoryCsv, CsvFieldsQuoteAndSplitBack) {
  const std::vector<std::string> fields = {"plain", "a,b", "say \"hi\"", "", "x:y"};
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + choc::csvField(fields[i]);
  EXPECT_EQ(choc::splitCsvLine(line), fields);
  EXPECT_EQ(choc::csvField("two\nlines"), "two lines");
  EXPECT_EQ(choc::csvNumber(0.1), "0.10000000000000001");
}

TEST(HistoryCsv, ReaderRejectsMalformedFiles) {
  const fs::path d = freshDir("history_reader");
  { std::ofstream(d / "a.csv") << "t,A:DX\n0,1\n"; }
  EXPECT_THROW(choc::readHistoryCsv((d / "a.csv").string()), std::runtime_error);
  { std::ofstream(d / "b.csv") << "time,A:DX\n0,1\n1\n"; }
  EXPECT_THROW(choc::readHistoryCsv((d / "b.csv").string()), std::runtime_error);
  { std::ofstream(d / "c.csv") << "time,A:DX\n0,abc\n"; }
  EXPECT_THROW(choc::readHistoryCsv((d / "c.csv").string()), std::runtime_error);
  EXPECT_THROW(choc::readHistoryCsv((d / "none.csv").string()), std::runtime_error);
}

}  // namespace
