#include "core/Resources.hpp"

#include <ctime>

#include <sys/resource.h>

#include <fstream>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

double peakResidentBytes() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return 1024.0 * std::stod(line.substr(6));  // kB
  return 0.0;
}

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void logPhase(const Teuchos::Comm<int>& comm, const std::string& phase, double seconds) {
  const int n = comm.getSize();
  std::vector<double> mine(n, 0.0), all(n, 0.0);
  mine[comm.getRank()] = peakResidentBytes();
  Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_SUM, n, mine.data(), all.data());
  std::string per;
  for (double b : all) per += format(" %.1f", b / 1048576.0);
  log() << format("  %s: %.3f s; peak memory per rank [MiB]:%s\n", phase.c_str(), seconds, per.c_str());
}

double wallClockSeconds() {
  timespec t{};
  clock_gettime(CLOCK_REALTIME, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace choc
