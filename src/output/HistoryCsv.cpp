#include "output/HistoryCsv.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>

#include "core/Errors.hpp"
#include "core/Files.hpp"

namespace choc {
namespace {

constexpr std::size_t kFlushEvery = 1000;        // rows: a history can be followed as it grows
constexpr std::size_t kBufferBytes = 1 << 16;     // or when this much is waiting

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
  removeFile(path_);
  removeFile(incompletePath(path_));
  fd_ = ::open(partPath().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw OutputError("history " + partPath() + ": cannot be created (" + systemError(errno) + ")");
  buffer_ = header();
  writeBuffer();
}

std::string HistoryCsv::header() const {
  std::string h = "time";
  for (const auto& c : columns_) h += "," + c;
  return h + "\n";
}

void HistoryCsv::checkResumable(const std::string& path, long long bytes) {
  HistoryCsv probe;
  probe.path_ = path;
  const std::string source = probe.resumeSource();
  if (source.empty())
    refuseResume(probe.partPath(), "no such file (nor " + incompletePath(path) + " or " + path + ")");
  struct stat st {};
  if (::stat(source.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size < bytes)
    refuseResume(source, "it has " + std::to_string(::stat(source.c_str(), &st) == 0 ? st.st_size : 0) +
                             " bytes, the checkpoint needs " + std::to_string(bytes));
}

std::string HistoryCsv::resumeSource() const {
  for (const std::string& p : {partPath(), incompletePath(path_), path_})
    if (isRegularFile(p)) return p;
  return "";
}

void HistoryCsv::refuseResume(const std::string& file, const std::string& why) {
  throw InputError(file + ": cannot continue the history of the checkpointed run: " + why +
                   "; restart with the results the checkpoint was written with, or run from the start");
}

HistoryCsv::HistoryCsv(const std::string& path, const std::vector<std::string>& columns,
                       const Resume& at, std::string& prefix)
    : path_(path), columns_(columns) {
  checkResumable(path, at.bytes);
  const std::string source = resumeSource();
  {
    std::ifstream in(source, std::ios::binary);
    prefix.assign(static_cast<std::size_t>(std::max(0LL, at.bytes)), '\0');
    in.read(prefix.data(), at.bytes);
    if (in.gcount() != at.bytes)
      refuseResume(source, "it has " + std::to_string(in.gcount()) + " bytes, the checkpoint needs " +
                               std::to_string(at.bytes));
  }
  std::size_t lines = 0;
  for (char c : prefix) lines += c == '\n';
  if (prefix.compare(0, header().size(), header()) != 0 || lines != at.rows + 1 ||
      (!prefix.empty() && prefix.back() != '\n'))
    refuseResume(source, "its first " + std::to_string(at.rows) + " rows are not the checkpoint's");
  if (source != partPath() && std::rename(source.c_str(), partPath().c_str()) != 0)
    refuseResume(source, "cannot rename it to " + partPath() + " (" + systemError(errno) + ")");
  if (::truncate(partPath().c_str(), at.bytes) != 0)
    refuseResume(partPath(), "cannot truncate it (" + systemError(errno) + ")");
  fd_ = ::open(partPath().c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) refuseResume(partPath(), "cannot open it for writing (" + systemError(errno) + ")");
  written_ = at.bytes;
  rows_ = at.rows;
}

// The buffer holds whole rows only: it is written with one call, and when the disk takes part
// of it the file is cut back to its last whole row, so a history never ends inside a row.
void HistoryCsv::writeBuffer() {
  if (buffer_.empty()) return;
  const int err = writeFully(fd_, buffer_.data(), buffer_.size());
  if (err != 0) {
    const int cut = ::ftruncate(fd_, static_cast<off_t>(written_));
    (void)cut;  // the error to report is the write's
    buffer_.clear();
    failed_ = true;
    throw OutputError("history " + partPath() + ": write failed (" + systemError(err) +
                      "; disk full or file-size limit?)");
  }
  written_ += static_cast<long long>(buffer_.size());
  buffer_.clear();
}

long long HistoryCsv::flush() {
  if (fd_ < 0) throw std::logic_error("history " + path_ + ": flush after finish/abandon");
  writeBuffer();
  return written_;
}

HistoryCsv::~HistoryCsv() {
  if (fd_ < 0) return;
  try {
    abandon();
  } catch (...) {
    // A destructor never throws; the .part file stays behind.
  }
}

void HistoryCsv::appendRow(double time, const std::vector<double>& values) {
  if (fd_ < 0) throw std::logic_error("history " + path_ + ": row appended after finish/abandon");
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
  buffer_ += csvNumber(time);
  for (double v : values) {
    buffer_ += ',';
    buffer_ += csvNumber(v);
  }
  buffer_ += '\n';
  if (++rows_ % kFlushEvery == 0 || buffer_.size() >= kBufferBytes) writeBuffer();
}

void HistoryCsv::closeAndRename(bool complete) {
  std::string failure;
  if (!failed_) {
    try {
      writeBuffer();
    } catch (const OutputError& e) {
      failure = e.what();
    }
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && failure.empty())
    failure = "history " + partPath() + ": closing failed (" + systemError(errno) + ")";
  const bool ok = complete && failure.empty() && !failed_;
  // A file with the final name is always complete: a failed write is renamed incomplete.
  const std::string target = ok ? path_ : incompletePath(path_);
  renameFile(partPath(), target);
  if (!failure.empty()) throw OutputError(failure + "; kept as " + target);
}

void HistoryCsv::finish() {
  if (fd_ < 0) throw std::logic_error("history " + path_ + ": finish after finish/abandon");
  closeAndRename(true);
}

void HistoryCsv::abandon() {
  if (fd_ < 0) return;
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
