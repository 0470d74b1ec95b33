// The one time grid of every transient (timeint/TimeGrid.hpp) and the one step loop over it
// (timeint/StepLoop.hpp), with a stepper that records what the loop asks of it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "timeint/StepLoop.hpp"

namespace choc {
namespace {

TEST(TimeGrid, WholeStepsEndAtTheEndTime) {
  const TimeGrid g(0.0, 1.02e-3, 1e-6);  // 1020 steps, (1020 * 1e-6 differs from 1.02e-3 by an ulp)
  EXPECT_EQ(g.steps(), 1020);
  EXPECT_EQ(g.stepEnd(1020), 1.02e-3);
  EXPECT_EQ(g.stepEnd(7), 7 * 1e-6);
  EXPECT_EQ(g.stepLength(1020), 1e-6);
}

TEST(TimeGrid, WithinOnePpmOfWholeStepsIsWholeSteps) {
  // 100 steps and 5e-5 of one: within 1e-6 of the span, so 100 steps of dt, not a 101st of
  // 5e-5 dt; at 2e-4 of a step over 100 steps (2e-6 of the span) the last step is cut.
  const TimeGrid near(0.0, 100.00005, 1.0);
  EXPECT_EQ(near.steps(), 100);
  EXPECT_EQ(near.stepLength(100), 1.0);
  EXPECT_EQ(near.stepEnd(100), 100.00005);
  const TimeGrid cut(0.0, 100.5, 1.0);
  EXPECT_EQ(cut.steps(), 101);
  EXPECT_DOUBLE_EQ(cut.stepLength(101), 0.5);
  EXPECT_EQ(cut.stepEnd(101), 100.5);
}

TEST(TimeGrid, StartsAtTheStartTime) {
  const TimeGrid g(2.0, 3.0, 0.25);
  EXPECT_EQ(g.steps(), 4);
  EXPECT_EQ(g.stepEnd(1), 2.25);
  EXPECT_EQ(g.stepEnd(4), 3.0);
}

TEST(TimeGrid, RefusesAnEmptyOrUnboundedGrid) {
  EXPECT_THROW(TimeGrid(1.0, 1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(TimeGrid(0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(TimeGrid(0.0, 1.0, 1e-300), std::invalid_argument);
}

// Takes each nominal step in `parts` accepted pieces (a stepper that cuts); records the calls.
struct RecordingStepper : Stepper {
  int parts = 1;
  std::vector<double> started, reported;
  std::vector<bool> boundaries;
  double state = 0;  // "integrates" dt: state is the time reached
  void start(double t0, double firstStep, TransientSummary& sum, StepInfo&) override {
    started.push_back(t0);
    state = t0;
    sum.smallestStep = firstStep;
  }
  Advance advance(const NominalStep& s, StepControl& c, TransientSummary&) override {
    if (c.cuts == 0) {  // the loop resets the control at each nominal step
      c.h = (s.target - s.t) / parts;
      c.cuts = 1;
    }
    const bool lastPart = c.h >= s.target - s.t - 1e-12;
    Advance a;
    a.time = lastPart ? s.target : s.t + c.h;
    a.dt = a.time - s.t;
    state = a.time;
    return a;
  }
  void notify(const StepInfo& info) override {
    reported.push_back(info.time);
    boundaries.push_back(info.boundary);
  }
  void archiveState(StateArchive& a, const StateVectors&) const override { a.putDouble("test/state", state); }
  void restoreState(const StateArchive& a, const StateVectors&) override { state = a.getDouble("test/state"); }
};

TEST(StepLoop, ReportsTheInitialStateAndEveryAcceptedOne) {
  RecordingStepper s;
  s.parts = 2;
  StepLoop loop(s, TimeGrid(1.0, 2.0, 0.5));
  const TransientSummary sum = loop.run();
  ASSERT_EQ(s.started, std::vector<double>{1.0});
  EXPECT_EQ(sum.steps, 4);  // two nominal steps in two accepted parts each
  EXPECT_EQ(s.reported, (std::vector<double>{1.0, 1.25, 1.5, 1.75, 2.0}));
  EXPECT_EQ(s.boundaries, (std::vector<bool>{true, false, true, false, true}));
  EXPECT_DOUBLE_EQ(sum.smallestStep, 0.25);
}

}  // namespace
}  // namespace choc
