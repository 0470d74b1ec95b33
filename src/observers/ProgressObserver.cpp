#include "observers/ProgressObserver.hpp"

#include <algorithm>

#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

ProgressObserver::ProgressObserver(double startTime, double endTime, double intervalSeconds)
    : start_(startTime), end_(endTime), interval_(intervalSeconds) {}

void ProgressObserver::begin(TransientView&) {
  wallStart_ = lastLine_ = std::chrono::steady_clock::now();
}

std::string ProgressObserver::line(double time, double startTime, double endTime, double wall) {
  const double span = endTime - startTime;
  const double done = span > 0 ? std::clamp((time - startTime) / span, 0.0, 1.0) : 1.0;
  std::string s = format("  t = %.4e s (%.1f%%), wall %.1f s", time, 100.0 * done, wall);
  if (done > 0 && done < 1) s += format(", about %.1f s left", wall * (1.0 - done) / done);
  return s;
}

void ProgressObserver::step(TransientView& view) {
  if (!(interval_ > 0) || !isRootRank()) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - lastLine_).count() < interval_) return;
  lastLine_ = now;
  const StepPoint pt = view.point();
  std::string s = line(pt.time, start_, end_, std::chrono::duration<double>(now - wallStart_).count());
  s += format("; step %lld", pt.step);
  const std::string note = view.stepNote();
  if (!note.empty()) s += ", " + note;
  if (const InteractionOutput* io = view.interactions()) s += ", " + io->progressNote();
  log() << s << "\n" << std::flush;
}

}  // namespace choc
