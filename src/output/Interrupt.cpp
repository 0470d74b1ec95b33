#include "output/Interrupt.hpp"

#include <csignal>
#include <cstdio>

#include <mpi.h>

namespace choc {

namespace {

volatile std::sig_atomic_t g_signal = 0;
volatile std::sig_atomic_t g_count = 0;

// The first signal asks for the clean stop. `timeout` signals the child and then its process
// group, and mpirun forwards what it receives: a second signal is taken as the same request.
// A third one stops the process at once (the default action).
extern "C" void onInterrupt(int sig) {
  if (++g_count >= 3) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  if (g_signal == 0) g_signal = sig;
}

}  // namespace

void installInterruptHandlers() {
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  // A file-size limit (ulimit -f) makes write() fail with EFBIG instead of killing the
  // process, so the writer reports the file and the results so far are kept.
  std::signal(SIGXFSZ, SIG_IGN);
}

void unblockInterruptSignals() {
  sigset_t both;
  sigemptyset(&both);
  sigaddset(&both, SIGINT);
  sigaddset(&both, SIGTERM);
  sigprocmask(SIG_UNBLOCK, &both, nullptr);
}

bool interruptRequested() { return g_signal != 0; }

int interruptSignal() { return g_signal; }

void setInterruptForTesting(int sig) {
  g_signal = sig;
  g_count = sig == 0 ? 0 : 1;
}

const char* signalName(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal";
  }
}

namespace {

int agreedSignal(MPI_Comm comm = MPI_COMM_WORLD) {
  int sig = g_signal;
  int initialized = 0, finalized = 0, size = 1;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Comm_size(comm, &size);
  if (size > 1) {
    int any = 0;
    MPI_Allreduce(&sig, &any, 1, MPI_INT, MPI_MAX, comm);
    sig = any;
  }
  return sig;
}

}  // namespace

void throwIfInterruptedBefore(const std::string& what) {
  const int sig = agreedSignal();
  if (sig != 0)
    throw Interrupted(sig, std::string(signalName(sig)) + " received: run stopped before " + what);
}

std::string interruptedMessage(int sig, const std::string& what, double time) {
  char t[64];
  std::snprintf(t, sizeof t, "%.6e", time);
  return std::string(signalName(sig)) + " received: " + what + " stopped at t = " + t +
         " s (the last completed step)";
}

void throwIfInterrupted(const std::string& what, double time, MPI_Comm comm) {
  const int sig = agreedSignal(comm);
  if (sig == 0) return;
  throw Interrupted(sig, interruptedMessage(sig, what, time));
}

}  // namespace choc
