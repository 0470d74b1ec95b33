#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "reference/BarImpactExact.hpp"
#include "reference/HistoryError.hpp"

namespace {

TEST(HistoryError, SyntheticSeries) {
  std::vector<double> t, y;
  for (int i = 0; i <= 10; ++i) {
    t.push_back(0.1 * i);
    y.push_back(2 * t.back());
  }
  y[5] += 0.3;
  y[7] -= 0.4;
  const auto e = choc::historyError(t, y, [](double s) { return 2 * s; });
  EXPECT_NEAR(e.maxAbs, 0.4, 1e-15);
  EXPECT_DOUBLE_EQ(e.timeOfMax, t[7]);
  EXPECT_NEAR(e.rms, std::sqrt((0.09 + 0.16) / 11), 1e-15);
  EXPECT_DOUBLE_EQ(e.peak, 2.0);
  EXPECT_NEAR(e.maxRelPeak, 0.2, 1e-15);
  EXPECT_NEAR(e.rmsRelPeak, e.rms / 2, 1e-15);
  EXPECT_EQ(e.samples, 11u);
  const auto s = choc::historyError(t, y, [](double s) { return 2 * s; }, 4.0);
  EXPECT_DOUBLE_EQ(s.peak, 4.0);
  EXPECT_NEAR(s.maxRelPeak, 0.1, 1e-15);
}

TEST(HistoryError, ExactHistoryHasZeroError) {
  choc::BarImpactParameters p;
  p.waveSpeed = 5000.0;
  p.impedance = 7800 * 5000 * 4e-4;
  const choc::BarImpactExact exact(p);
  std::vector<double> t, y;
  for (int i = 0; i <= 1020; ++i) {
    t.push_back(1e-6 * i);
    y.push_back(exact.displacementA(t.back()));
  }
  const auto e = choc::historyError(t, y, [&](double s) { return exact.displacementA(s); },
                                    exact.peakDisplacement());
  EXPECT_EQ(e.maxAbs, 0.0);
  EXPECT_EQ(e.maxRelPeak, 0.0);
}

TEST(HistoryError, RefusesWhatWouldGiveNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto id = [](double s) { return s; };
  EXPECT_THROW(choc::historyError({0, 1}, {0, nan}, id), std::invalid_argument);
  EXPECT_THROW(choc::historyError({0, nan}, {0, 1}, id), std::invalid_argument);
  EXPECT_THROW(choc::historyError({0, 1}, {0, 1}, [&](double) { return nan; }),
               std::invalid_argument);
  EXPECT_THROW(choc::historyError({0, 1}, {0}, id), std::invalid_argument);
  EXPECT_THROW(choc::historyError({}, {}, id), std::invalid_argument);
  EXPECT_THROW(choc::historyError({0, 1}, {0, 1}, [](double) { return 0.0; }),
               std::invalid_argument);  // zero peak, none supplied
  EXPECT_THROW(choc::historyError({0, 1}, {0, 1}, id, 0.0), std::invalid_argument);
  EXPECT_THROW(choc::historyError({0, 1}, {0, 1}, id, nan), std::invalid_argument);
  EXPECT_NO_THROW(choc::historyError({0, 1}, {0, 1}, [](double) { return 0.0; }, 1.0));
}

}  // namespace
