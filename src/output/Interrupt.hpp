// Interruption by SIGINT / SIGTERM. installInterruptHandlers() makes the first signal only
// set a flag; the time loops test it at a step boundary (throwIfInterrupted) and throw
// choc::Interrupted, so that the outputs are closed and renamed "*.incomplete.*" on the way
// out and the process exits with 128 + the signal number (130 for SIGINT, 143 for SIGTERM).
// A second signal is the same request (`timeout` and `mpirun` signal twice); a third one kills
// the process at once (the default action): the files then stay as "*.part", never with the
// name of a complete result. The handlers are installed before MPI starts, so a signal during
// the set-up is a clean stop too, reported before the first analysis.
#pragma once
#include <mpi.h>

#include <stdexcept>
#include <string>

#include "core/Errors.hpp"

namespace choc {

// A run stopped on request. Not a NumericalError: it has its own exit code.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& message)
      : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }
  int exitCode() const { return kExitInterruptBase + signal_; }

 private:
  int signal_;
};

void installInterruptHandlers();
void unblockInterruptSignals();   // SIGINT and SIGTERM, blocked by the launcher
bool interruptRequested();        // on this process
int interruptSignal();            // the signal received, 0 if none
const char* signalName(int sig);  // "SIGINT", "SIGTERM", ...
// Throws Interrupted naming 'what' and the time when a signal was received. On more than one
// MPI rank every rank of `comm` (the analysis's communicator) must call it at the same step
// boundary: the flag is reduced over it (a rank that did not see the signal stops too).
void throwIfInterrupted(const std::string& what, double time, MPI_Comm comm = MPI_COMM_WORLD);
// The message throwIfInterrupted gives.
std::string interruptedMessage(int sig, const std::string& what, double time);
// The same between two analyses: "<signal> received: run stopped before <what>".
void throwIfInterruptedBefore(const std::string& what);
// For tests: as if the signal had been received (0 clears the flag).
void setInterruptForTesting(int sig);

}  // namespace choc
