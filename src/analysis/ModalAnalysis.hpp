// Modal analysis: the N modes nearest a shift (or the N lowest) by Anasazi, each checked by
// its true residual; writes <name>.exo (one step per mode, time = frequency in Hz) and
// <name>.modes.csv, and keeps the basis for modal transient analyses of the same input.
#pragma once
#include "analysis/Analysis.hpp"

namespace choc {

class ModalAnalysis : public Analysis {
 public:
  using Analysis::Analysis;
  static Teuchos::ParameterList parameters();
  void run(RunContext& ctx) override;
};

}  // namespace choc
