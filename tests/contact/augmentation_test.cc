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
#include "support/recorded_run.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::Outcome;
using test::Warned;

// A sheet dropped on a sphere: the penalty alone sinks the pole 4.7 % of h.
TEST(Augmentation, EveryStepMeetsItsTargetOrSaysWhatItReached) {
  test::SheetSpec spec;
  const Scene scene = test::SheetOverSphere(spec, 0.05);
  const double target = 0.005 * spec.thickness;

  // The promise: with the default passes every step is within its target.
  const Outcome kept = test::SolveRecorded(scene, SolverOptions::FromScene(scene.solver));
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
  const Outcome penalty = test::SolveRecorded(scene, none);
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

}  // namespace
}  // namespace drape
