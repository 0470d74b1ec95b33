#include "timeint/StepLoop.hpp"

#include <algorithm>

namespace choc {

void StepLoop::startState(StepInfo& info) {
  t_ = grid_.start();
  nominal_ = 0;
  stepper_.start(t_, grid_.stepEnd(1) - t_, sum_, info);
  info.time = t_;
  info.step = 0;
  info.nominal = 0;
  stepper_.notify(info);
}

void StepLoop::resumeState(const Resume& r) {
  t_ = r.archive.getDouble("driver/time");
  nominal_ = r.archive.getInt("driver/nominal");
  sum_ = r.archive.getPod<TransientSummary>("driver/summary");
  stepper_.restoreState(r.archive, r.vectors);
}

void StepLoop::archive(StateArchive& a, const StateVectors& vectors) const {
  a.putDouble("driver/time", t_);
  a.putInt("driver/nominal", nominal_);
  a.putPod("driver/summary", sum_);
  stepper_.archiveState(a, vectors);
}

// Nominal step n, by the accepted states the stepper reaches; each is shown to the observers.
void StepLoop::nominalStep(long long n, StepInfo& info) {
  const NominalStep s0{n, t_, grid_.stepEnd(n), grid_.dt(), grid_.stepLength(n)};
  StepControl control{s0.target - t_, 0};
  while (t_ < s0.target) {
    NominalStep s = s0;
    s.t = t_;
    const Advance a = stepper_.advance(s, control, sum_);
    ++sum_.steps;
    sum_.maxNewtonPerStep = std::max(sum_.maxNewtonPerStep, a.newton.iterations);
    sum_.smallestStep = std::min(sum_.smallestStep, a.substep > 0 ? a.substep : a.dt);
    t_ = a.time;
    const bool boundary = t_ >= s0.target;
    if (boundary) nominal_ = n;
    info.step = sum_.steps;
    info.time = t_;
    info.dt = a.dt;
    info.newton = a.newton;
    info.cuts = control.cuts;
    info.last = boundary && n == grid_.steps();
    info.boundary = boundary;
    info.nominal = nominal_;
    info.substep = a.substep;
    stepper_.notify(info);
  }
}

TransientSummary StepLoop::run(const Resume* resume) {
  sum_ = TransientSummary();
  StepInfo info;
  if (resume)
    resumeState(*resume);
  else
    startState(info);
  info.time = t_;
  info.step = sum_.steps;
  info.nominal = nominal_;
  for (long long n = nominal_ + 1; n <= grid_.steps(); ++n) nominalStep(n, info);
  return sum_;
}

}  // namespace choc
