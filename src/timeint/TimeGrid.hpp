// The nominal time grid of a transient: steps of dt from the start time, the last one cut to
// the end time. The count is computed in floating point, so no step length can overflow it;
// the analyses refuse a count above their 'Maximum Steps' before any loop uses it.
#pragma once

namespace choc {

// ceil((end - start) / dt), less a step that would only cover round-off (1e-9 of dt); at
// least 1. Infinity when dt is not positive or the ratio is not finite.
double nominalSteps(double start, double end, double dt);

// The largest count a step counter may take (the analyses' 'Maximum Steps' stays below it).
constexpr double kLargestStepCount = 1e15;

}  // namespace choc
