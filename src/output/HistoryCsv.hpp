// <analysis>.history.csv (docs/user-guide/running.md, "What a run writes"): first column
// "time", then one column per quantity.
// Rows go to "<path>.part"; finish() renames it to <path>, abandon() to the ".incomplete"
// name, so a file with the final name is always a complete history of this run.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace choc {

// Shared CSV helpers (also used by checks.csv).
std::string csvNumber(double v);                // "%.17g": reads back to the same double
std::string csvField(const std::string& text);  // RFC 4180 quoting when needed
std::vector<std::string> splitCsvLine(const std::string& line);  // inverse of csvField
// "run.history.csv" -> "run.history.incomplete.csv"; "name" -> "name.incomplete".
std::string incompletePath(const std::string& path);

class HistoryCsv {
 public:
  // columns: the quantities after "time" (non-empty, distinct, not "time").
  // Removes stale <path> and its ".incomplete" file from an earlier run.
  // Throws std::invalid_argument for bad names, choc::InputError if the file cannot be opened.
  HistoryCsv(const std::string& path, const std::vector<std::string>& columns);
  // Continues the history of a checkpointed run: the first `bytes` bytes (the header and
  // `rows` rows) of <path>.part, or of the .incomplete or final file when the earlier run
  // ended; rows after them are dropped. Throws InputError naming the file when it is missing or
  // does not hold that header and those rows. `prefix` receives the kept text.
  struct Resume {
    std::size_t rows = 0;
    long long bytes = 0;
  };
  HistoryCsv(const std::string& path, const std::vector<std::string>& columns, const Resume& at,
             std::string& prefix);
  // Throws the InputError the resuming constructor would when <path>'s earlier file is missing
  // or shorter than `bytes`, without changing anything (a refused restart writes nothing).
  static void checkResumable(const std::string& path, long long bytes);
  ~HistoryCsv();  // abandon() unless finished
  HistoryCsv(const HistoryCsv&) = delete;
  HistoryCsv& operator=(const HistoryCsv&) = delete;

  // values: one per column. Throws choc::NumericalError naming the column and the time if
  // a value (or the time) is not finite, std::invalid_argument on a size mismatch. Rows are
  // written whole: on a failed write (OutputError) the file is cut back to its last whole row.
  void appendRow(double time, const std::vector<double>& values);
  // Flushes the rows written so far and returns the file's length (for a checkpoint).
  // Throws OutputError naming the file when the data cannot be written.
  long long flush();
  void finish();   // flush, close, rename <path>.part -> <path>
  void abandon();  // close, rename <path>.part -> incompletePath(path)

  const std::string& path() const { return path_; }
  std::string partPath() const { return path_ + ".part"; }
  std::size_t rows() const { return rows_; }
  bool open() const { return fd_ >= 0; }

 private:
  HistoryCsv() = default;
  void closeAndRename(bool complete);
  void writeBuffer();
  std::string resumeSource() const;
  [[noreturn]] static void refuseResume(const std::string& file, const std::string& why);
  std::string header() const;
  std::string path_;
  std::vector<std::string> columns_;
  int fd_ = -1;
  std::string buffer_;     // whole rows not yet written
  long long written_ = 0;  // bytes of whole rows in the file
  bool failed_ = false;
  std::size_t rows_ = 0;
};

// A history file read back: names[0] == "time"; rows[i][j] is column j of row i.
struct HistoryTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::size_t index(const std::string& name) const;             // std::out_of_range if absent
  std::vector<double> column(const std::string& name) const;    // all rows of one column
  bool has(const std::string& name) const;
};

// Throws std::runtime_error naming the file and line on a missing file or a malformed row.
HistoryTable readHistoryCsv(const std::string& path);
// The same from text already read (`name` for messages).
HistoryTable parseHistoryCsv(const std::string& text, const std::string& name);

}  // namespace choc
