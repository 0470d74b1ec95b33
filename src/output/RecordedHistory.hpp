// The history of a transient kept in memory for the checks: times and one series per column.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace choc {

struct RecordedHistory {
  std::vector<double> times;
  std::map<std::string, std::vector<double>> columns;
  // Scalars of the whole run for the checks, e.g. "stop:impact 2:peak force" (ImpactObserver).
  std::map<std::string, double> statistics;
};

}  // namespace choc
