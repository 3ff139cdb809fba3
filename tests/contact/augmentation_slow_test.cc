// A failed augmented-Lagrangian pass is undone whole: the reactions reported
// are those of the state kept (the diagonal fold: slow, labelled `slow`).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/io/scene_reader.h"
#include "support/recorded_run.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::Outcome;
using test::Warned;

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
  const Outcome run = test::SolveRecorded(scene, options);
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
