// Parts held on a form by friction (μ = 0.3) alone, no pin (issue 35): the
// scarf of resources/scenes/dress-form-drape.json without its pin, and a
// sheet on a ball. Frictionless, a scarf hung over the neck is a chain over a
// pulley; with the regularised friction it replaced, the scarf's path
// diverged at λ ≈ 0.0015 and the sheet's found no branch past λ = 0.489.
// ~25 s and ~17 s: the slow tier.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/io/scene_reader.h"
#include "core/model/scene.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// Solves `scene`, counting the steps with negative pivots.
struct HeldRun {
  SolveSummary summary;
  StepState last;
  int unstable_steps = 0;
  double weight = 0;
};
HeldRun SolveHeld(const Scene& scene) {
  HeldRun run;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  run.summary = solver.Solve({[&](const StepState& step) {
    if (step.negative_pivots > 0) ++run.unstable_steps;
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
}

TEST(FormFriction, AnUnpinnedScarfRestsOnTheFormOnAStablePath) {
  Scene scene = ReadScene(test::ScenesDir() / "dress-form-drape.json");
  scene.supports.clear();
  scene.contact->friction = 0.3;
  scene.solver.branching = Branching::kStable;
  const HeldRun run = SolveHeld(scene);
  ExpectHeldStablyByFriction(run);
  if (HasFatalFailure()) return;
  const SolveSummary& summary = run.summary;
  const StepState& last = run.last;
  const double weight = run.weight;
  // Friction holds part of it: the scarf's ends pull it down the shoulders.
  EXPECT_GT(last.contact->friction_force.z(), 0.05 * weight);
  // The form is mirror-symmetric about x = 0: both ends hang alike, past
  // the shoulders (z ≈ 0.5 m) and outside the body (half-width ≤ 0.16 m).
  const Eigen::Vector3d left = last.probes[0].value, right = last.probes[1].value;
  EXPECT_NEAR(left.x(), -right.x(), 1e-6);
  EXPECT_NEAR(left.z(), right.z(), 1e-6);
  EXPECT_LT(left.z(), 0.45);
  EXPECT_GT(std::abs(left.x()), 0.11);
  EXPECT_LT(std::abs(left.x()), 0.2);
  std::printf(
      "unpinned scarf, mu = 0.3: %d steps, ends at (%.4f, %.4f) m; friction "
      "carries %.3f of the weight; %d nodes stick, %d slide\n",
      summary.steps,
      right.x(),
      right.z(),
      last.contact->friction_force.z() / weight,
      last.contact->sticking,
      last.contact->sliding);
}

// A 10 × 10 cm sheet (20 × 20, B = 5e-6 N·m, 1.5 N/m², E = 5 MPa, h = 0.5
// mm) laid flat on a ball of radius 3 cm: it must wrinkle to drape, snaps
// twice on the way, and rests held by the cap's friction.
TEST(FormFriction, ASheetOnABallRestsWithoutAPinOnAStablePath) {
  Scene scene;
  scene.name = "sheet on a ball, mu 0.3";
  scene.fabric.outline = RectangleOutline{{0.1, 0.1}, {0, 0}};
  scene.fabric.mesh.elements = std::array<int, 2>{20, 20};
  scene.material.thickness = 5e-4;
  scene.material.areal_weight = 1.5;
  scene.material.membrane = IsotropicMembrane{5e6, 0.3};
  scene.material.bending.warp = LinearBending{5e-6};
  scene.obstacles.push_back({"ball", SphereShape{{0, 0, -0.03025}, 0.03}});
  scene.contact = Contact{};
  scene.contact->friction = 0.3;
  scene.solver.branching = Branching::kStable;
  Stage stage;
  stage.name = "weight";
  stage.initial_increment = 0.05;
  scene.stages.push_back(stage);
  const HeldRun run = SolveHeld(scene);
  ExpectHeldStablyByFriction(run);
  if (HasFatalFailure()) return;
  const SolveSummary& summary = run.summary;
  const StepState& last = run.last;
  const double weight = run.weight;
  std::printf(
      "sheet on a ball, mu = 0.3: %d steps; friction carries %.3f of the weight; %d "
      "nodes stick, %d slide\n",
      summary.steps,
      last.contact->friction_force.z() / weight,
      last.contact->sticking,
      last.contact->sliding);
}

}  // namespace
}  // namespace drape
