// What a process has used so far: peak resident memory and CPU time, and a log line giving
// a phase's wall time with every rank's peak memory (for large meshes: read, partition,
// assembly).
#pragma once
#include <string>

#include <Teuchos_Comm.hpp>

namespace choc {

double peakResidentBytes();  // VmHWM of /proc/self/status (0 if unknown)
double cpuSeconds();         // user + system
double wallClockSeconds();   // seconds since the epoch (file times compare with it)

// Logs "  <phase>: <seconds> s; peak memory per rank [MiB]: a b ..." (collective).
void logPhase(const Teuchos::Comm<int>& comm, const std::string& phase, double seconds);

}  // namespace choc
