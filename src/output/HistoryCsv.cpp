#include "output/HistoryCsv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <unistd.h>
#include <stdexcept>

#include "core/Errors.hpp"

namespace choc {
namespace {

constexpr std::size_t kFlushEvery = 1000;

void removeIfPresent(const std::string& path) { std::remove(path.c_str()); }

}  // namespace

std::string csvNumber(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string csvField(const std::string& text) {
  std::string s = text;
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';  // one record per line, always
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  return out;
}

std::string incompletePath(const std::string& path) {
  const std::string ext = ".csv";
  if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
    return path.substr(0, path.size() - ext.size()) + ".incomplete.csv";
  return path + ".incomplete";
}

HistoryCsv::HistoryCsv(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns) {
  std::set<std::string> seen{"time"};
  for (const auto& c : columns) {
    if (c.empty()) throw std::invalid_argument("history " + path + ": empty column name");
    if (c.find_first_of(",\"\n\r") != std::string::npos)
      throw std::invalid_argument("history " + path + ": column name '" + c +
                                  "' contains a comma, a quote or a line break");
    if (!seen.insert(c).second)
      throw std::invalid_argument("history " + path + ": column '" + c +
                                  "' is repeated (or is 'time', which is always the first)");
  }
  removeIfPresent(path_);
  removeIfPresent(incompletePath(path_));
  file_ = std::fopen(partPath().c_str(), "w");
  if (!file_)
    throwInput(partPath(), "output directory", "", std::string("cannot be opened for writing (") +
               std::strerror(errno) + ")", "check that the output directory exists and is writable");
  if (std::fputs(header().c_str(), file_) == EOF)
    throw OutputError("history " + partPath() + ": write failed (" + std::strerror(errno) + ")");
}

std::string HistoryCsv::header() const {
  std::string h = "time";
  for (const auto& c : columns_) h += "," + c;
  return h + "\n";
}

HistoryCsv::HistoryCsv(const std::string& path, const std::vector<std::string>& columns,
                       const Resume& at, std::string& prefix)
    : path_(path), columns_(columns) {
  std::string source;
  for (const std::string& p : {partPath(), incompletePath(path_), path_})
    if (std::ifstream(p).good()) {
      source = p;
      break;
    }
  const auto refuse = [&](const std::string& file, const std::string& why) {
    throw InputError(file + ": cannot continue the history of the checkpointed run: " + why +
                     "; restart with the results the checkpoint was written with, or run from the start");
  };
  if (source.empty()) refuse(partPath(), "no such file (nor " + incompletePath(path_) + " or " + path_ + ")");
  {
    std::ifstream in(source, std::ios::binary);
    prefix.assign(static_cast<std::size_t>(std::max(0LL, at.bytes)), '\0');
    in.read(prefix.data(), at.bytes);
    if (in.gcount() != at.bytes)
      refuse(source, "it has " + std::to_string(in.gcount()) + " bytes, the checkpoint needs " +
                         std::to_string(at.bytes));
  }
  std::size_t lines = 0;
  for (char c : prefix) lines += c == '\n';
  if (prefix.compare(0, header().size(), header()) != 0 || lines != at.rows + 1 ||
      (!prefix.empty() && prefix.back() != '\n'))
    refuse(source, "its first " + std::to_string(at.rows) + " rows are not the checkpoint's");
  if (source != partPath() && std::rename(source.c_str(), partPath().c_str()) != 0)
    refuse(source, std::string("cannot rename it to ") + partPath() + " (" + std::strerror(errno) + ")");
  if (::truncate(partPath().c_str(), at.bytes) != 0)
    refuse(partPath(), std::string("cannot truncate it (") + std::strerror(errno) + ")");
  file_ = std::fopen(partPath().c_str(), "a");
  if (!file_) refuse(partPath(), std::string("cannot open it for writing (") + std::strerror(errno) + ")");
  rows_ = at.rows;
}

long long HistoryCsv::flush() {
  if (!file_) throw std::logic_error("history " + path_ + ": flush after finish/abandon");
  if (std::fflush(file_) != 0 || std::ferror(file_))
    throw OutputError("history " + partPath() + ": write failed (" + std::strerror(errno) +
                      "; disk full or file-size limit?)");
  return static_cast<long long>(std::ftell(file_));
}

HistoryCsv::~HistoryCsv() {
  if (!file_) return;
  try {
    abandon();
  } catch (...) {
    // A destructor never throws; the .part file stays behind.
  }
}

void HistoryCsv::appendRow(double time, const std::vector<double>& values) {
  if (!file_) throw std::logic_error("history " + path_ + ": row appended after finish/abandon");
  if (values.size() != columns_.size())
    throw std::invalid_argument("history " + path_ + ": row at time " + csvNumber(time) + " has " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns");
  if (!std::isfinite(time))
    throw NumericalError("history " + path_ + ": time is " + csvNumber(time) +
                         " after row " + std::to_string(rows_));
  for (std::size_t j = 0; j < values.size(); ++j)
    if (!std::isfinite(values[j]))
      throw NumericalError("history " + path_ + ": column '" + columns_[j] + "' is " +
                           csvNumber(values[j]) + " at time " + csvNumber(time));
  std::string line = csvNumber(time);
  for (double v : values) line += "," + csvNumber(v);
  line += "\n";
  const bool failed = std::fputs(line.c_str(), file_) == EOF ||
                      (++rows_ % kFlushEvery == 0 && std::fflush(file_) != 0);
  if (failed)
    throw OutputError("history " + partPath() + ": write failed (" + std::strerror(errno) +
                      "; disk full or file-size limit?)");
}

void HistoryCsv::closeAndRename(bool complete) {
  std::FILE* f = file_;
  file_ = nullptr;
  const bool writeFailed = std::fflush(f) != 0 || std::ferror(f) != 0;
  const bool closeFailed = std::fclose(f) != 0;
  const bool ok = complete && !writeFailed && !closeFailed;
  // A file with the final name is always complete: a failed write is renamed incomplete.
  const std::string target = ok ? path_ : incompletePath(path_);
  if (std::rename(partPath().c_str(), target.c_str()) != 0)
    throw std::runtime_error("history " + path_ + ": cannot rename " + partPath() + " to " +
                             target + " (" + std::strerror(errno) + ")");
  if (writeFailed || closeFailed)
    throw OutputError("history " + path_ + ": write failed (disk full or file-size limit?); kept as " + target);
}

void HistoryCsv::finish() {
  if (!file_) throw std::logic_error("history " + path_ + ": finish after finish/abandon");
  closeAndRename(true);
}

void HistoryCsv::abandon() {
  if (!file_) return;
  closeAndRename(false);
}

std::size_t HistoryTable::index(const std::string& name) const {
  for (std::size_t j = 0; j < names.size(); ++j)
    if (names[j] == name) return j;
  throw std::out_of_range("history: no column '" + name + "'");
}

bool HistoryTable::has(const std::string& name) const {
  for (const auto& n : names)
    if (n == name) return true;
  return false;
}

std::vector<double> HistoryTable::column(const std::string& name) const {
  const std::size_t j = index(name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(r[j]);
  return out;
}

HistoryTable readHistoryCsv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot be opened for reading");
  std::ostringstream text;
  text << file.rdbuf();
  return parseHistoryCsv(text.str(), path);
}

HistoryTable parseHistoryCsv(const std::string& content, const std::string& path) {
  std::istringstream in(content);
  HistoryTable t;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file (no header)");
  t.names = splitCsvLine(line);
  if (t.names.empty() || t.names[0] != "time")
    throw std::runtime_error(path + ":1: the first column must be 'time'");
  std::size_t lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto fields = splitCsvLine(line);
    if (fields.size() != t.names.size())
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " +
                               std::to_string(fields.size()) + " fields, header has " +
                               std::to_string(t.names.size()));
    std::vector<double> row;
    row.reserve(fields.size());
    for (const auto& f : fields) {
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      if (f.empty() || *end != '\0')
        throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": '" + f +
                                 "' is not a number");
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace choc
