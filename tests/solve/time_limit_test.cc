// solver.max_wall_s: a run past its wall-clock limit stops with
// Termination::kTimeLimit, says so, and keeps every step it converged; a
// user's cancellation stays a cancellation.
#include <gtest/gtest.h>

#include <string>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

struct LimitedRun {
  SolveSummary summary;
  int observed = 0;
};

LimitedRun Solve(const Scene& scene,
                 const SolverOptions& options,
                 const CancellationToken* cancel) {
  ShellSolver solver(scene, options);
  LimitedRun run;
  run.summary = solver.Solve({[&](const StepState&) {
                               ++run.observed;
                               return StepDecision::kContinue;
                             }},
                             cancel);
  return run;
}

// The diagonal fold takes seconds; a limit of a tenth of a second stops it
// on the way, whatever the machine.
TEST(TimeLimit, ARunPastItsLimitStopsAndKeepsItsSteps) {
  const Scene scene = ReadScene(test::ScenesDir() / "diagonal-fold.json");
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  options.max_wall_s = 0.1;
  const LimitedRun run = Solve(scene, options, nullptr);
  EXPECT_EQ(run.summary.termination, Termination::kTimeLimit) << run.summary.FullReport();
  EXPECT_FALSE(run.summary.IsComplete());
  EXPECT_NE(run.summary.message.find("time limit of 0.1 s (solver.max_wall_s"), std::string::npos)
      << run.summary.message;
  EXPECT_NE(run.summary.message.find("in stage '"), std::string::npos) << run.summary.message;
  EXPECT_EQ(run.observed, run.summary.steps);  // every converged step went to the observers
  EXPECT_STREQ(ToString(run.summary.termination), "time limit");
}

TEST(TimeLimit, TheScenesKeyAndNoLimit) {
  Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  scene.solver.max_wall_s = 1e-9;
  EXPECT_EQ(Solve(scene, SolverOptions::FromScene(scene.solver), nullptr).summary.termination,
            Termination::kTimeLimit);
  scene.solver.max_wall_s = 600;  // far beyond the run
  EXPECT_TRUE(Solve(scene, SolverOptions::FromScene(scene.solver), nullptr).summary.IsComplete());
  scene.solver.max_wall_s.reset();
  EXPECT_EQ(SolverOptions::FromScene(scene.solver).max_wall_s, 0);
}

TEST(TimeLimit, ACancellationIsNotATimeLimit) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  options.max_wall_s = 600;
  CancellationToken user;
  user.Cancel();
  const LimitedRun run = Solve(scene, options, &user);
  EXPECT_EQ(run.summary.termination, Termination::kCancelled) << run.summary.message;
}

TEST(TimeLimit, ANegativeLimitIsInvalid) {
  SolverOptions options;
  options.max_wall_s = -1;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("max_wall_s"), std::string::npos) << error;
}

}  // namespace
}  // namespace drape
