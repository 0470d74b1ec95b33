// The progress line of a long run: simulated time, percent of the run, wall time so far and
// the estimate of the time left (elapsed x remaining fraction / done fraction).
#include <gtest/gtest.h>

#include "observers/ProgressObserver.hpp"

namespace choc {
namespace {

TEST(Progress, PercentAndEstimateOfTheTimeLeft) {
  // 40% of [0, 1e-3] done in 12 s: 18 s left at the same pace.
  EXPECT_EQ(ProgressObserver::line(4e-4, 0.0, 1e-3, 12.0),
            "  t = 4.0000e-04 s (40.0%), wall 12.0 s, about 18.0 s left");
  // A run that starts later: the fraction is of [start, end].
  EXPECT_EQ(ProgressObserver::line(0.75, 0.5, 1.5, 3.0),
            "  t = 7.5000e-01 s (25.0%), wall 3.0 s, about 9.0 s left");
}

TEST(Progress, NoEstimateAtTheEnds) {
  EXPECT_EQ(ProgressObserver::line(0.0, 0.0, 1.0, 0.5), "  t = 0.0000e+00 s (0.0%), wall 0.5 s");
  EXPECT_EQ(ProgressObserver::line(1.0, 0.0, 1.0, 7.0), "  t = 1.0000e+00 s (100.0%), wall 7.0 s");
}

}  // namespace
}  // namespace choc
