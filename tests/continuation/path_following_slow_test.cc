// Whole runs of the path follower that take tens of seconds (minutes under
// the sanitizers, hence the slow tier: tests/CMakeLists.txt): the paper's
// acceleration, a branch that bends back, and a path through a reversed load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "core/io/scene_reader.h"
#include "core/mechanics/director.h"
#include "core/model/solver_preset.h"
#include "core/solve/shell_solver.h"
#include "support/recorded_run.h"
#include "support/test_paths.h"

namespace drape {
namespace {

TEST(PathFollowing, AccelerationNeedsTenTimesFewerSteps) {
  // The paper's Table 3: 45 steps with acceleration, 1994 without (R's Δλ₀ is
  // 0.009 with and 0.0009 without).
  Scene with = ReadScene(test::ScenesDir() / "strip-fold-no-table.json");
  Scene without = with;
  without.solver.acceleration = false;
  without.solver.max_steps = 100000;
  without.stages[1].initial_increment = 0.0009;
  test::Outcome fast = test::SolveRecorded(with);
  test::Outcome slow = test::SolveRecorded(without);
  test::PrintStages("with acceleration", fast.summary);
  test::PrintStages("without acceleration", slow.summary);
  ASSERT_TRUE(fast.summary.IsComplete());
  ASSERT_TRUE(slow.summary.IsComplete());
  EXPECT_GE(slow.summary.steps, 10 * fast.summary.steps);
  // Both end in the same state (docs/validation.md §5, the no-table
  // column): every node's position and director, not only the gripped end
  // the stages carry to the same place by construction. Measured: 1.02e-10 m
  // and 4.3e-9 (each run converged to the scene's tolerance, 1e-6); held to
  // about three times that.
  const ShellState &a = fast.steps.back().state, &b = slow.steps.back().state;
  ASSERT_EQ(a.NodeCount(), b.NodeCount());
  double position = 0, director = 0;
  for (int i = 0; i < a.NodeCount(); ++i) {
    position = std::max(position, (a.positions.row(i) - b.positions.row(i)).norm());
    director = std::max(director, (a.Director(i) - b.Director(i)).norm());
  }
  const Eigen::Vector3d p = test::Probe(fast.steps.back(), "fold"),
                        q = test::Probe(slow.steps.back(), "fold");
  std::printf(
      "  end states: largest node distance %.3g m, director difference %.3g; fold probe "
      "with (%.5f, %.5f, %.5f), without (%.5f, %.5f, %.5f) m\n",
      position,
      director,
      p.x(),
      p.y(),
      p.z(),
      q.x(),
      q.y(),
      q.z());
  EXPECT_LT(position, 3e-10);
  EXPECT_LT(director, 1.3e-8);
}

// A branch that bends back: on this wavy sheet hung from four pins the
// switch at λ = 0.9337 lands on a stable state a little behind the
// bifurcation, and forward from there leads back to it. Once sent forward
// on every definite tangent, the run went round between the two states
// until max_steps; now a second landing on the same state lets the path go
// the way the switch pointed, and the run ends (here where the part would
// snap) in tens of steps.
TEST(PathFollowing, ABranchThatBendsBackIsNotGoneRoundForever) {
  Scene scene = ReadScene(test::SourceDir() / "tests" / "data" / "block-pins-seed19.json");
  scene.solver.max_steps = 400;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  std::map<long, int> landings;  // switches per landing λ (to 1e-6)
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    if (s.stability_event && s.stability_event->branch == Branch::kStable)
      ++landings[std::lround(s.lambda * 1e6)];
    return StepDecision::kContinue;
  }});
  EXPECT_NE(summary.termination, Termination::kMaxStepsReached) << summary.message;
  EXPECT_LT(summary.steps, 200) << summary.message;
  for (const auto& [lambda, count] : landings) EXPECT_LE(count, 2) << "λ = " << lambda * 1e-6;
  std::printf("%d steps, %zu landing points: %s\n",
              summary.steps,
              landings.size(),
              summary.message.c_str());
}

// Seed 2 of the same sheet used to reach λ = 1 only through a reversed load
// (down to λ = −0.93, then up again), where a real part jumps. Now it does
// jump: λ never falls below 0, every step is stable, at least one snap, and
// nothing to warn of. (The warning itself: the thin roof under its point
// load, tests/verification/hinged_roof_test.cc.) A path that never goes below
// λ = 0 (the diagonal fold, above) has no such warning either.
TEST(PathFollowing, ASheetThatRanBackThroughAReversedLoadNowSnaps) {
  auto warns = [](const SolveSummary& summary) {
    for (const auto& w : summary.warnings)
      if (w.find("only after its path ran back to λ = ") != std::string::npos) return true;
    return false;
  };
  Scene scene = ReadScene(test::SourceDir() / "tests" / "data" / "block-pins-seed2.json");
  double lowest = 0;
  int unstable = 0;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    lowest = std::min(lowest, s.lambda);
    unstable += s.negative_pivots > 0;
    return StepDecision::kContinue;
  }});
  std::printf("%s\n", summary.BriefReport().c_str());
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(lowest, 0.0);
  EXPECT_EQ(unstable, 0);
  EXPECT_FALSE(warns(summary));
  EXPECT_GE(std::count_if(summary.stability_events.begin(),
                          summary.stability_events.end(),
                          [](const StabilityEvent& e) { return e.kind == StabilityKind::kSnap; }),
            1);
  Scene fold = ReadScene(test::ScenesDir() / "diagonal-fold.json");
  fold.solver = WithPreset(fold.solver, SolverPreset::kDraft);
  ShellSolver folding(fold, SolverOptions::FromScene(fold.solver));
  const SolveSummary folded = folding.Solve({});
  ASSERT_TRUE(folded.IsComplete()) << folded.message;
  EXPECT_FALSE(warns(folded));
}

}  // namespace
}  // namespace drape
