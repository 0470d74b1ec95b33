// Checkpoints of a transient and its interruption (SIGINT/SIGTERM). At the end of a nominal
// step (never a sub-step of a cut one, nor the final state) it writes <base>.checkpoint when
// 'Checkpoint/Interval Steps' steps have passed since the start, when 'Interval Seconds' of
// wall time have passed since the last checkpoint, or when a signal was received; then, on a
// signal, it stops the run (Interrupted). The signal and the wall-time test are agreed by
// every rank at the same states (every `every` states; one reduction for both). The
// checkpoint holds the run's identity (input and mesh), the state the analysis gives
// (time stepper, contact, links, energy integrals) and the other observers' (file positions).
#pragma once
#include <mpi.h>

#include <chrono>
#include <functional>
#include <string>

#include "observers/TransientObserver.hpp"
#include "restart/RunIdentity.hpp"

namespace choc {

struct CheckpointSettings {
  long long intervalSteps = 0;  // 0: none
  double intervalSeconds = 0;   // 0: none
};

struct CheckpointPlan {
  std::string path;  // "<base>.checkpoint"
  CheckpointSettings settings;
  RunIdentity identity;
  std::function<void(StateArchive&)> archiveRun;  // the analysis's state (collective)
};

class CheckpointObserver : public TransientObserver {
 public:
  // history (may be null): its pending write failure is agreed on with the signal.
  CheckpointObserver(std::string what, MPI_Comm comm, long long every, CheckpointPlan plan,
                     const ObserverSet& outputs, const class HistoryObserver* history = nullptr);
  void step(TransientView& view) override;

 private:
  void write(const StepPoint& pt);
  std::string what_;
  MPI_Comm comm_;
  long long every_;
  CheckpointPlan plan_;
  const ObserverSet& outputs_;
  std::chrono::steady_clock::time_point last_;
  long long testStep_;  // CHOC_TEST_SIGNAL_AT_STEP (-1: none)
  const class HistoryObserver* history_;
};

}  // namespace choc
