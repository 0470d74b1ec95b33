// <analysis>.summary.json: what one analysis of a run did, in a form tools read (the log is
// for people and may change). Fields are set as the analysis goes; the command writes the
// file when the analysis ends, completed or not, with its status and exit reason.
//
// Keys are paths with '/' between levels ("timers/linear_solve/max"; no name of an analysis,
// pair or link holds a '/'); objects keep the order in which their first key was set. Numbers that are not finite are written as null.
#pragma once
#include <string>
#include <variant>
#include <vector>

namespace choc {

class RunSummary {
 public:
  void set(const std::string& key, double value);
  void set(const std::string& key, long long value);
  void set(const std::string& key, int value) { set(key, static_cast<long long>(value)); }
  void set(const std::string& key, bool value);
  void set(const std::string& key, const std::string& value);
  void set(const std::string& key, const char* value) { set(key, std::string(value)); }
  void set(const std::string& key, const std::vector<double>& values);
  bool has(const std::string& key) const;
  std::string json() const;  // one object, indented, ending with a newline

 private:
  using Value = std::variant<double, long long, bool, std::string, std::vector<double>>;
  std::vector<std::pair<std::string, Value>> entries_;
  void put(const std::string& key, Value v);
};

// JSON text of a string (quoted, escaped).
std::string jsonString(const std::string& text);

}  // namespace choc
