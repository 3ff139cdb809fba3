// SolveSummary's one-line report: "converged" alone only for a state a real
// part can rest in (no negative pivots at the end).
#include "core/solve/solve_summary.h"

#include <gtest/gtest.h>

#include <string>

namespace drape {
namespace {

SolveSummary Completed(int final_negative_pivots) {
  SolveSummary s;
  s.termination = Termination::kCompleted;
  s.message = "every stage reached λ = 1";
  s.steps = 27;
  s.final_negative_pivots = final_negative_pivots;
  return s;
}

bool StartsWith(const std::string& text, const std::string& start) {
  return text.rfind(start, 0) == 0;
}

TEST(SolveSummary, ConvergedAloneIsAStableEnd) {
  EXPECT_TRUE(StartsWith(Completed(0).BriefReport(), "converged: 27 steps"))
      << Completed(0).BriefReport();
  EXPECT_TRUE(StartsWith(Completed(1).BriefReport(),
                         "converged to an unstable equilibrium (1 negative pivot): 27 steps"))
      << Completed(1).BriefReport();
  EXPECT_TRUE(StartsWith(Completed(8).BriefReport(),
                         "converged to an unstable equilibrium (8 negative pivots): 27 steps"))
      << Completed(8).BriefReport();
  // A run that stopped says why, whatever its last state's inertia.
  SolveSummary failed = Completed(3);
  failed.termination = Termination::kStepTooSmall;
  EXPECT_TRUE(StartsWith(failed.BriefReport(), "step too small: 27 steps")) << failed.BriefReport();
}

}  // namespace
}  // namespace drape
