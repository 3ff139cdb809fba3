// Parts held on a form by friction (μ = 0.3) alone, no pin (issue 35), with
// barrier contact: resources/scenes/scarf-on-form.json (the scarf of
// dress-form-drape.json without its pin) and sheet-on-ball.json. Frictionless,
// a scarf hung over the neck is a chain over a pulley; with the regularised
// friction it replaced, the scarf's path diverged at λ ≈ 0.0015 and the
// sheet's found no branch past λ = 0.489. On every accepted step no node's
// mid-surface comes within h/2 of the obstacle (the distance measured here
// from the states). ~8 s and ~6 s: the slow tier.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "core/io/scene_reader.h"
#include "core/model/obstacle_geometry.h"
#include "core/model/scene.h"
#include "core/solve/shell_solver.h"
#include "support/scarf_ends.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// Solves `scene`, counting the steps with negative pivots and taking the
// smallest gap − h/2 − (distance of a node's mid-surface to the obstacle)
// over every node of every step; `distance` is the obstacle's.
struct HeldRun {
  SolveSummary summary;
  StepState last;
  int unstable_steps = 0;
  double weight = 0;
  double smallest_gap = INFINITY;  // [m]
};
HeldRun SolveHeld(const Scene& scene,
                  const std::function<double(const Eigen::Vector3d&)>& distance) {
  HeldRun run;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  const double half = 0.5 * scene.material.thickness;
  run.summary = solver.Solve({[&](const StepState& step) {
    if (step.negative_pivots > 0) ++run.unstable_steps;
    for (int i = 0; i < step.state.NodeCount(); ++i)
      run.smallest_gap =
          std::min(run.smallest_gap, distance(step.state.positions.row(i).transpose()) - half);
    run.last = step;
    return StepDecision::kContinue;
  }});
  run.weight = solver.model().total_weight.norm();
  return run;
}

// The run completed with 0 negative pivots at every step, and nothing but
// the obstacle holds the part: its normal and friction forces carry the
// weight to 1e-6 (measured 3e-9 and 3e-10), and some nodes stick.
void ExpectHeldStablyByFriction(const HeldRun& run) {
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  EXPECT_EQ(run.unstable_steps, 0) << run.summary.FullReport();
  ASSERT_TRUE(run.last.contact.has_value());
  EXPECT_NEAR(run.last.contact->force.z(), run.weight, 1e-6 * run.weight);
  EXPECT_NEAR(run.last.contact->force.head<2>().norm(), 0.0, 1e-6 * run.weight);
  EXPECT_GT(run.last.contact->sticking, 0);
  // The barrier: never at or inside the obstacle, on any step.
  EXPECT_GT(run.smallest_gap, 0.0);
  EXPECT_EQ(run.summary.max_penetration, 0.0);
}

TEST(FormFriction, AnUnpinnedScarfRestsOnTheFormOnAStablePath) {
  const Scene scene = ReadScene(test::ScenesDir() / "scarf-on-form.json");
  ASSERT_TRUE(scene.supports.empty() && scene.grippers.empty());
  ASSERT_EQ(scene.contact->friction, 0.3);
  const auto form = MakeObstacleGeometry(scene.obstacles.at(0), test::ScenesDir());
  const HeldRun run =
      SolveHeld(scene, [&](const Eigen::Vector3d& x) { return form->Query(x).distance; });
  ExpectHeldStablyByFriction(run);
  if (HasFatalFailure()) return;
  const SolveSummary& summary = run.summary;
  const StepState& last = run.last;
  const double weight = run.weight;
  // Friction holds part of it: the scarf's ends pull it down the shoulders.
  EXPECT_GT(last.contact->friction_force.z(), 0.05 * weight);
  const Eigen::Vector3d right = last.probes[1].value;
  test::ExpectScarfEndsHangAlongTheBody(last.probes[0].value, right);
  std::printf(
      "unpinned scarf, mu = 0.3: %d steps, ends at (%.4f, %.4f) m; friction "
      "carries %.3f of the weight; %d nodes stick, %d slide; closest gap %.3g h\n",
      summary.steps,
      right.x(),
      right.z(),
      last.contact->friction_force.z() / weight,
      last.contact->sticking,
      last.contact->sliding,
      run.smallest_gap / scene.material.thickness);
}

// A 10 × 10 cm sheet (20 × 20, B = 5e-6 N·m, 1.5 N/m², E = 5 MPa, h = 0.5
// mm) laid flat on a ball of radius 3 cm: it snaps on the way, and rests
// bent over the cap, held by its friction.
TEST(FormFriction, ASheetOnABallRestsWithoutAPinOnAStablePath) {
  const Scene scene = ReadScene(test::ScenesDir() / "sheet-on-ball.json");
  ASSERT_TRUE(scene.supports.empty() && scene.grippers.empty());
  ASSERT_EQ(scene.contact->friction, 0.3);
  // The ball's distance from its centre and radius, as the scene states them.
  const auto& ball = std::get<SphereShape>(scene.obstacles.at(0).shape);
  const Eigen::Vector3d centre(ball.center[0], ball.center[1], ball.center[2]);
  ASSERT_NEAR(ball.radius, 0.03, 1e-15);
  const HeldRun run =
      SolveHeld(scene, [&](const Eigen::Vector3d& x) { return (x - centre).norm() - ball.radius; });
  ExpectHeldStablyByFriction(run);
  if (HasFatalFailure()) return;
  const SolveSummary& summary = run.summary;
  const StepState& last = run.last;
  const double weight = run.weight;
  std::printf(
      "sheet on a ball, mu = 0.3: %d steps; friction carries %.3f of the weight; %d "
      "nodes stick, %d slide; closest gap %.3g h\n",
      summary.steps,
      last.contact->friction_force.z() / weight,
      last.contact->sticking,
      last.contact->sliding,
      run.smallest_gap / scene.material.thickness);
}

}  // namespace
}  // namespace drape
