// The nominal time grid of every transient (direct implicit, explicit, modal): steps of dt
// from the start time to the end time.
//   - A span within 1e-6 (relative) of a whole number of steps is that many steps of dt (the
//     last one ends at the end time);
//   - otherwise the last step is cut to the end time: ceil((end - start) / dt) steps, less a
//     step that would only cover round-off (1e-9 of dt).
// Steppers may cut a nominal step further (implicit step control, explicit and modal
// sub-steps): the grid is what the output and the checkpoints count. The count is computed in
// floating point, so no step length can overflow it; the analyses refuse a count above their
// 'Maximum Steps' before any loop uses it.
#pragma once

namespace choc {

// ceil((end - start) / dt), less a step that would only cover round-off (1e-9 of dt); at
// least 1. Infinity when dt is not positive or the ratio is not finite.
double nominalSteps(double start, double end, double dt);

// The largest count a step counter may take (the analyses' 'Maximum Steps' stays below it).
constexpr double kLargestStepCount = 1e15;

class TimeGrid {
 public:
  // Needs dt > 0 and end > start with a step count the caller has checked (checkStepCount):
  // std::invalid_argument otherwise.
  TimeGrid(double start, double end, double dt);
  double start() const { return start_; }
  double end() const { return end_; }
  double dt() const { return dt_; }
  long long steps() const { return steps_; }
  // Step n (1..steps) ends at start + n dt, the last one at the end time.
  double stepEnd(long long n) const { return n >= steps_ ? end_ : start_ + double(n) * dt_; }
  // The length a stepper takes for step n: dt, or the last step cut to the end time.
  double stepLength(long long n) const { return n >= steps_ ? lastStep_ : dt_; }

 private:
  double start_, end_, dt_;
  long long steps_ = 0;
  double lastStep_ = 0;
};

}  // namespace choc
