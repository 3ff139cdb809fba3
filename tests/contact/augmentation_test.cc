// The augmented-Lagrangian passes of the "auto" penalty: each converged step
// either holds the penetration under its target (0.5 % of the thickness) or
// says what it reached; and a pass that fails is undone whole — the reactions
// reported are those of the state kept.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/contact_scenes.h"
#include "support/test_paths.h"

namespace drape {
namespace {

struct Outcome {
  SolveSummary summary;
  std::vector<StepState> steps;
};

Outcome Solve(const Scene& scene, const SolverOptions& options) {
  ShellSolver solver(scene, options);
  Outcome run;
  run.summary = solver.Solve({[&](const StepState& s) {
    run.steps.push_back(s);
    return StepDecision::kContinue;
  }});
  return run;
}

bool Warned(const SolveSummary& summary, const std::string& what) {
  return std::any_of(summary.warnings.begin(), summary.warnings.end(), [&](const std::string& w) {
    return w.find(what) != std::string::npos;
  });
}

// A sheet dropped on a sphere: the penalty alone sinks the pole 4.7 % of h.
TEST(Augmentation, EveryStepMeetsItsTargetOrSaysWhatItReached) {
  test::SheetSpec spec;
  const Scene scene = test::SheetOverSphere(spec, 0.05);
  const double target = 0.005 * spec.thickness;

  // The promise: with the default passes every step is within its target.
  const Outcome kept = Solve(scene, SolverOptions::FromScene(scene.solver));
  ASSERT_TRUE(kept.summary.IsComplete()) << kept.summary.FullReport();
  int passes = 0;
  for (const StepState& s : kept.steps) {
    ASSERT_TRUE(s.contact);
    EXPECT_DOUBLE_EQ(s.contact->penetration_target, target);
    EXPECT_LE(s.contact->max_penetration, target) << "step " << s.step;
    EXPECT_TRUE(s.contact->augmentation_shortfall.empty()) << s.contact->augmentation_shortfall;
    passes += s.contact->augmentation_passes;
  }
  EXPECT_GT(passes, 0);
  EXPECT_FALSE(Warned(kept.summary, "penetration target"));

  // No passes allowed: every step that sinks deeper says so, and the summary
  // names the deepest.
  SolverOptions none = SolverOptions::FromScene(scene.solver);
  none.max_augmentations = 0;
  const Outcome penalty = Solve(scene, none);
  ASSERT_TRUE(penalty.summary.IsComplete()) << penalty.summary.FullReport();
  double deepest = 0;
  int short_steps = 0;
  for (const StepState& s : penalty.steps) {
    const bool over = s.contact->max_penetration > target;
    EXPECT_EQ(!s.contact->augmentation_shortfall.empty(), over) << "step " << s.step;
    short_steps += over;
    deepest = std::max(deepest, s.contact->max_penetration);
  }
  std::printf("penalty alone: deepest %.3g m = %.2f %% of h, %d steps over the target\n",
              deepest,
              100 * deepest / spec.thickness,
              short_steps);
  EXPECT_GT(short_steps, 0);
  EXPECT_EQ(penalty.summary.penetration_target_missed, short_steps);
  EXPECT_DOUBLE_EQ(penalty.summary.worst_missed_penetration, deepest);
  EXPECT_TRUE(Warned(penalty.summary, "penetration target")) << penalty.summary.FullReport();
}

// The diagonal fold with one Newton iteration allowed per pass: passes fail
// and are undone. The gripper's reaction is then recomputed independently
// from the state the step reports (the gripped corner is in the air, so its
// force is the shell's own, with no contact in it) and must agree to
// round-off; the failed pass's last iterate differs by ~1e-5 of it. Without
// self-contact, whose force on the corner as it lands the shell-only system
// here does not hold.
TEST(Augmentation, ReactionsAfterAnUndonePassAreThoseOfTheStateKept) {
  Scene scene = ReadScene(test::ScenesDir() / "diagonal-fold-linear.json");
  scene.contact->self = false;
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  options.max_augmentation_iterations = 1;
  const Outcome run = Solve(scene, options);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();

  const ShellModel model = BuildShellModel(scene);
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  for (const auto& g : model.grippers)
    for (int node : g.nodes) dofs.FixNode(node, g.fixity);
  EquilibriumSystem shell_only(model, dofs);  // no contact
  const HeldNodes& corner = model.grippers.front();

  int undone = 0;
  double worst = 0;
  for (const StepState& s : run.steps) {
    if (s.stage != 1 ||
        s.contact->augmentation_shortfall.find("did not converge") == std::string::npos)
      continue;
    ++undone;
    shell_only.Assemble(s.state, /*with_tangent=*/false);
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    for (int node : corner.nodes)
      expected += (shell_only.InternalForce() - model.weight_load).segment<3>(kDofsPerNode * node);
    Eigen::Vector3d reported = Eigen::Vector3d::Zero();
    for (const auto& r : s.reactions)
      if (r.name == corner.name) reported = r.value;
    worst = std::max(worst, (reported - expected).norm() / expected.norm());
    EXPECT_LT((reported - expected).norm(), 1e-9 * expected.norm()) << "step " << s.step;
  }
  std::printf(
      "%d steps with an undone pass; worst relative reaction difference %.2e\n", undone, worst);
  EXPECT_GE(undone, 3);
  EXPECT_TRUE(Warned(run.summary, "did not converge")) << run.summary.FullReport();
}

}  // namespace
}  // namespace drape
