#include "observers/RunLimits.hpp"

#include <cmath>
#include <limits>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "input/ParameterSpec.hpp"
#include "timeint/TimeGrid.hpp"

namespace choc {

namespace {
constexpr double kBytesPerCsvNumber = 24;  // "%.17g" and its comma
constexpr double kGigabyte = 1e9;
}  // namespace

void declareRunLimits(Teuchos::ParameterList& p) {
  declareDouble(p, "Maximum Steps", 1e8,
                "the largest number of time steps (sub-steps included) the run may take: a run "
                "that needs more is refused before it starts (raise it for a run that is meant to "
                "be that long)",
                Range::closed(1, kLargestStepCount));
  declareDouble(p, "Maximum Output Size", 20.0,
                "the largest size [GB] the history and Exodus files are expected to reach (from the "
                "steps, the recorded columns, 'Exodus Interval' and the mesh): a run expected to "
                "write more is refused before it starts",
                Range::positive());
}

RunLimits readRunLimits(const Teuchos::ParameterList& p) {
  return {p.get<double>("Maximum Steps"), p.get<double>("Maximum Output Size") * kGigabyte};
}

double OutputEstimate::bytes() const {
  const double history = (steps + 1) * (historyColumns + 1) * kBytesPerCsvNumber;
  const double states = exodusInterval > 0 ? std::floor(steps / exodusInterval) + 2 : 0.0;
  return history + states * double(nodes) * nodalFields * sizeof(double);
}

void checkStepCount(double steps, double substeps, const RunLimits& limits, const std::string& file,
                    const std::string& path, double timeStep) {
  const double total = steps * substeps;
  // Sub-steps are counted in an int: more than that is beyond any limit too.
  if (total <= limits.maxSteps && substeps <= std::numeric_limits<int>::max()) return;
  const std::string count = substeps > 1 ? format("%.4g steps of %.4g sub-steps", steps, substeps)
                                         : format("%.4g steps", steps);
  throwInput(file, path + "/Time Step", shortNumber(timeStep),
             "the run would take " + count + ", more than 'Maximum Steps' = " +
                 format("%.4g", limits.maxSteps),
             "check the time step and the end time, or raise '" + path + "/Maximum Steps'");
}

void checkOutputSize(const OutputEstimate& e, const RunLimits& limits, const std::string& file,
                     const std::string& path) {
  const double bytes = e.bytes();
  if (bytes <= limits.maxOutputBytes) return;
  throwInput(file, path + "/Maximum Output Size", format("%.4g", limits.maxOutputBytes / kGigabyte),
             format("the history (%.4g rows of %d columns)%s would take about %.3g GB", e.steps + 1,
                    e.historyColumns + 1,
                    e.exodusInterval > 0 ? format(" and the Exodus file (every %d steps)", e.exodusInterval).c_str()
                                         : "",
                    bytes / kGigabyte),
             "raise 'Exodus Interval', record fewer quantities, shorten the run, or raise "
             "'Maximum Output Size' [GB]");
}

}  // namespace choc
