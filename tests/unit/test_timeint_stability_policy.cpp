// The one stability policy of the explicit schemes (timeint/StabilityPolicy.hpp), branch by
// branch: below the stable step, within 1e-6 of it, above it with each 'Stability Check', and
// the switching springs' half of the critical step.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "timeint/StabilityPolicy.hpp"

using namespace choc;

TEST(StabilityPolicy, CriticalStepOfTheUndampedAndDampedSchemes) {
  EXPECT_DOUBLE_EQ(explicitCriticalStep(1e3, 0.0), 2e-3);
  const double xi = 0.1;  // 2/omega (sqrt(1 + xi^2) - xi)
  EXPECT_NEAR(explicitCriticalStep(1e3, xi), 2e-3 * (std::sqrt(1.01) - 0.1), 1e-18);
  EXPECT_TRUE(std::isinf(explicitCriticalStep(0.0, 0.0)));
}

TEST(StabilityPolicy, BelowTheStableStepOneStep) {
  for (StabilityCheck c : {StabilityCheck::Refuse, StabilityCheck::Warn, StabilityCheck::Substep}) {
    const StabilityDecision d = decideStability(0.9e-6, 1e-6, Switching::None, c);
    EXPECT_FALSE(d.above);
    EXPECT_FALSE(d.refused);
    EXPECT_FALSE(d.warned);
    EXPECT_EQ(d.substeps, 1);
    EXPECT_DOUBLE_EQ(d.stableStep, 1e-6);
  }
}

TEST(StabilityPolicy, WithinOnePpmOfTheLimitIsAbove) {
  // At the limit the highest mode grows linearly: a step within 1e-6 of it is above it.
  EXPECT_TRUE(decideStability(1e-6 * (1 - 1e-7), 1e-6, Switching::None, StabilityCheck::Refuse).refused);
  EXPECT_FALSE(decideStability(1e-6 * (1 - 2e-6), 1e-6, Switching::None, StabilityCheck::Refuse).refused);
}

TEST(StabilityPolicy, AboveRefuseWarnOrSubstep) {
  const StabilityDecision r = decideStability(3e-6, 1e-6, Switching::None, StabilityCheck::Refuse);
  EXPECT_TRUE(r.above && r.refused && !r.warned);
  EXPECT_NE(r.reason.find("exceeds the stable step of the explicit scheme, 1e-06 s"), std::string::npos) << r.reason;
  const StabilityDecision w = decideStability(3e-6, 1e-6, Switching::None, StabilityCheck::Warn);
  EXPECT_TRUE(w.above && w.warned && !w.refused);
  EXPECT_EQ(w.substeps, 1);
  const StabilityDecision s = decideStability(3e-6, 1e-6, Switching::None, StabilityCheck::Substep);
  EXPECT_TRUE(s.above && !s.refused && !s.warned);
  EXPECT_EQ(s.substeps, 4);  // ceil(3 / 0.9): sub-steps of at most 0.9 of the stable step
  EXPECT_LE(3e-6 / s.substeps, kSubstepSafety * 1e-6);
}

TEST(StabilityPolicy, SwitchingSpringsGetHalfTheCriticalStep) {
  const StabilityDecision d = decideStability(0.6e-6, 1e-6, Switching::PenaltyLinks, StabilityCheck::Refuse);
  EXPECT_DOUBLE_EQ(d.stableStep, 0.5e-6);
  EXPECT_TRUE(d.refused);
  EXPECT_NE(d.reason.find("half the critical step"), std::string::npos) << d.reason;
  EXPECT_FALSE(decideStability(0.6e-6, 1e-6, Switching::None, StabilityCheck::Refuse).refused);
  EXPECT_EQ(decideStability(0.6e-6, 1e-6, Switching::PenaltyLinks, StabilityCheck::Substep).substeps, 2);  // 0.6 / 0.45
}

TEST(StabilityPolicy, PenaltyContactGetsLessThanLinks) {
  const StabilityDecision d = decideStability(0.2e-6, 1e-6, Switching::PenaltyContact, StabilityCheck::Refuse);
  EXPECT_DOUBLE_EQ(d.stableStep, 0.15e-6);
  EXPECT_TRUE(d.refused);
  EXPECT_NE(d.reason.find("0.15 of the critical step"), std::string::npos) << d.reason;
  EXPECT_NE(d.reason.find("penalty contact creates energy"), std::string::npos) << d.reason;
  EXPECT_FALSE(decideStability(0.2e-6, 1e-6, Switching::PenaltyLinks, StabilityCheck::Refuse).refused);
  // 0.2 / (0.9 x 0.15) = 1.48: two sub-steps.
  EXPECT_EQ(decideStability(0.2e-6, 1e-6, Switching::PenaltyContact, StabilityCheck::Substep).substeps, 2);
}

TEST(StabilityPolicy, NamesOfTheChecks) {
  EXPECT_EQ(stabilityCheckFromName("refuse"), StabilityCheck::Refuse);
  EXPECT_EQ(stabilityCheckFromName("warn"), StabilityCheck::Warn);
  EXPECT_EQ(stabilityCheckFromName("substep"), StabilityCheck::Substep);
  EXPECT_THROW(stabilityCheckFromName("ignore"), std::invalid_argument);
}
