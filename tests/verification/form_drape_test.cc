// A scarf over a meshed dress form (resources/scenes/dress-form-drape.json):
// contact with a closed triangle mesh, read from resources/forms, holding a
// strip pinned at one point, which on the frictionless form is what lets it
// rest: unpinned it ended with 8 negative pivots.
#include <gtest/gtest.h>

#include <cmath>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/scarf_ends.h"
#include "support/test_paths.h"

namespace drape {
namespace {

TEST(FormDrape, ScarfOverTheDressFormCarriesItsWeightSymmetrically) {
  Scene scene = ReadScene(test::ScenesDir() / "dress-form-drape.json");
  // Equilibrium to 1e-8 of the force level, so the force balance below can
  // be checked to 1e-6.
  scene.solver.tolerance = 1e-8;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  StepState last;
  double deepest = 0;
  const SolveSummary summary = solver.Solve({[&](const StepState& step) {
    deepest = std::max(deepest, step.contact->max_penetration);
    last = step;
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  // A state a real scarf rests in: the tangent positive definite.
  EXPECT_EQ(last.negative_pivots, 0);
  EXPECT_TRUE(summary.warnings.empty()) << summary.FullReport();
  const double weight = solver.model().total_weight.norm();
  // At rest, the form and the pin carry the weight, to the Newton
  // tolerance; the pin only keeps the strip from sliding off, so the form
  // carries nearly all of it.
  ASSERT_EQ(last.reactions.size(), 1u);
  const Eigen::Vector3d held = last.contact->force + last.reactions[0].value;
  EXPECT_NEAR(held.z(), weight, 1e-6 * weight);
  EXPECT_NEAR(held.head<2>().norm(), 0.0, 1e-6 * weight);
  EXPECT_GT(last.contact->force.z(), 0.99 * weight);
  const Eigen::Vector3d left = last.probes[0].value, right = last.probes[1].value;
  test::ExpectScarfEndsHangAlongTheBody(left, right);
  // The auto penalty keeps penetration a few percent of the thickness even
  // where the strip bends over the neck cap's sharp rim (measured 2.5 %);
  // a flat support gives far less (the table tests).
  EXPECT_LT(deepest, 0.05 * scene.material.thickness);
  std::printf("scarf: %d steps, ends at (%.4f, %.4f) m, deepest penetration %.3g h\n",
              summary.steps,
              right.x(),
              right.z(),
              deepest / scene.material.thickness);
}

}  // namespace
}  // namespace drape
