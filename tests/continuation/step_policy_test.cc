// The paper's acceleration (step_policy.h): after a step of length ℓ that
// took N iterations the next is γℓ, γ = N_p/N clipped to [min, max]; off,
// every step keeps its length. Expected values are worked by hand from that
// rule (N_p = 7, bounds [0.25, 4] by default).
#include "core/continuation/step_policy.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace drape {
namespace {

TEST(StepPolicy, GrowsOrShrinksByTheTargetOverTheIterationsTaken) {
  const StepPolicy policy;                          // N_p = 7
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 7), 0.3);       // γ = 1
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 14), 0.15);     // γ = 1/2
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 2), 1.05);      // γ = 7/2
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 5), 0.42);      // γ = 7/5
  EXPECT_DOUBLE_EQ(policy.Next(2.0, 20), 0.7);      // γ = 7/20
  EXPECT_DOUBLE_EQ(policy.Next(1e-6, 4), 1.75e-6);  // γ = 7/4, at any scale
  EXPECT_DOUBLE_EQ(policy.Next(-0.3, 14), -0.15);   // a signed increment keeps its sign
}

TEST(StepPolicy, ClipsTheGrowthToItsBounds) {
  const StepPolicy policy;                        // γ in [0.25, 4]
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 1), 1.2);     // 7 → 4
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 28), 0.075);  // exactly 1/4
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 30), 0.075);  // 7/30 → 1/4
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 1000), 0.075);
  // A step that needed no iteration at all grows by the most allowed.
  EXPECT_DOUBLE_EQ(policy.Next(0.3, 0), 1.2);

  StepPolicy narrow;
  narrow.target_iterations = 4;
  narrow.min_step_growth = 0.5;
  narrow.max_step_growth = 2.0;
  EXPECT_DOUBLE_EQ(narrow.Next(1.0, 1), 2.0);  // 4 → 2
  EXPECT_DOUBLE_EQ(narrow.Next(1.0, 3), 4.0 / 3);
  EXPECT_DOUBLE_EQ(narrow.Next(1.0, 5), 0.8);
  EXPECT_DOUBLE_EQ(narrow.Next(1.0, 8), 0.5);
  EXPECT_DOUBLE_EQ(narrow.Next(1.0, 9), 0.5);  // 4/9 → 1/2
}

// Over every iteration count a run can report: the rule as stated, and a
// step that took more iterations is never followed by a longer one.
TEST(StepPolicy, FollowsTheRuleAndNeverGrowsWithMoreIterations) {
  const StepPolicy policy;
  double last = policy.Next(1.0, 1);
  for (int n = 1; n <= 100; ++n) {
    const double gamma = std::clamp(7.0 / n, 0.25, 4.0);
    EXPECT_DOUBLE_EQ(policy.Next(0.02, n), 0.02 * gamma) << n << " iterations";
    const double next = policy.Next(1.0, n);
    EXPECT_LE(next, last) << n << " iterations";
    last = next;
  }
}

TEST(StepPolicy, WithoutAccelerationEveryStepKeepsItsLength) {
  StepPolicy policy;
  policy.acceleration = false;
  for (int n : {0, 1, 3, 7, 12, 30, 500}) EXPECT_EQ(policy.Next(0.37, n), 0.37) << n;
}

}  // namespace
}  // namespace drape
