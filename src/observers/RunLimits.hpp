// Limits that keep a run from being endless or filling the disk by accident (a time step
// written 1e-12 too small, an interval of 1): the nominal step count, counting sub-steps, and
// the size the history and Exodus files are expected to reach. Both are refused by
// `choc check` and `choc run` before anything is computed, with the figure and the key that
// raises the limit.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace choc {

void declareRunLimits(Teuchos::ParameterList& analysis);

struct RunLimits {
  double maxSteps = 1e8;
  double maxOutputBytes = 20e9;
};
RunLimits readRunLimits(const Teuchos::ParameterList& analysis);

// What a transient is expected to write.
struct OutputEstimate {
  double steps = 0;          // recorded states (one history row each)
  int historyColumns = 0;    // after "time"
  int exodusInterval = 0;    // 0: no Exodus file
  long long nodes = 0;
  int nodalFields = 0;       // DISP_X ... and the interactions' fields
  double bytes() const;
};

// Throws InputError naming 'Time Step' when the run takes more than 'Maximum Steps' steps
// (`steps` nominal steps of `substeps` sub-steps each).
void checkStepCount(double steps, double substeps, const RunLimits& limits, const std::string& file,
                    const std::string& analysisPath, double timeStep);
// Throws InputError naming 'Maximum Output Size' when the estimate exceeds it.
void checkOutputSize(const OutputEstimate& e, const RunLimits& limits, const std::string& file,
                     const std::string& analysisPath);

}  // namespace choc
