// Progress of a long run on the log: every `interval` seconds of wall time, the simulated
// time with its percent of the run, the wall time so far and an estimate of the time left,
// then the solver's and the interactions' notes. Rank 0 decides and prints alone (nothing
// collective happens here), so its wall clock cannot desynchronise the ranks.
#pragma once
#include <chrono>
#include <string>

#include "observers/TransientObserver.hpp"

namespace choc {

class ProgressObserver : public TransientObserver {
 public:
  // interval <= 0: no progress lines.
  ProgressObserver(double startTime, double endTime, double intervalSeconds);
  void begin(TransientView& view) override;
  void step(TransientView& view) override;

  // "  t = 1.2000e-03 s (60.0%), wall 3.1 s, about 2.1 s left" (exposed for tests).
  static std::string line(double time, double startTime, double endTime, double wallSeconds);

 private:
  double start_, end_, interval_;
  std::chrono::steady_clock::time_point wallStart_, lastLine_;
};

}  // namespace choc
