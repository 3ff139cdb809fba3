// The paper's convergence study of a folded cotton twill strip (Eischen,
// Deng & Clapp, IEEE CG&A 1996, Figs. 13–15), run with the cotton's measured
// nonlinear law and with its linear equivalent (Kawabata B): both must
// complete, carry their weight, converge with the mesh as the paper found
// (essentially converged at 40 elements), and stay within the curvature
// range the law was fitted over. docs/bending.md shows the two shapes.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

struct FoldRun {
  SolveSummary summary;
  StepState last;
  double weight = 0;
  double valid_to = 0;
};

FoldRun Fold(int elements, bool linear) {
  Scene scene =
      ReadScene(test::ScenesDir() / ("strip-convergence-" + std::to_string(elements) + ".json"));
  if (linear) {
    // The paper's linear equivalent: B = 0.589 gf·cm²/cm (its Kawabata B),
    // 1 gf·cm²/cm = 1 gf·cm = 9.80665e-5 N·m²/m.
    scene.material.bending.warp = LinearBending{0.589 * 9.80665e-5};
  }
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  FoldRun run;
  run.summary = solver.Solve({[&](const StepState& step) {
    run.last = step;
    return StepDecision::kContinue;
  }});
  run.weight = solver.model().total_weight.norm();
  run.valid_to = solver.model().bending_valid_to;
  return run;
}

// Height of the loop: the highest midsurface point above the table [cm].
double LoopHeight(const FoldRun& run) {
  return 100 * run.last.state.positions.col(2).maxCoeff();
}

void ExpectCompleteAndBalanced(const FoldRun& run) {
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  Eigen::Vector3d held = run.last.contact->force;
  for (const auto& r : run.last.reactions) held += r.value;
  EXPECT_NEAR(held.z(), run.weight, 1e-4 * run.weight);
  EXPECT_NEAR(held.head<2>().norm(), 0.0, 1e-4 * run.weight);
  EXPECT_LT(run.summary.max_penetration, 0.01 * 0.0489e-2);  // 1 % of h
}

TEST(CottonStripFold, NonlinearAndLinearLawsBothFoldTheStrip) {
  std::printf("%8s %9s %10s %8s %12s %10s\n",
              "elements",
              "law",
              "loop [cm]",
              "steps",
              "max K [1/cm]",
              "time [s]");
  double loop[2][2] = {};
  for (int law = 0; law < 2; ++law) {
    const bool linear = law == 1;
    for (int m = 0; m < 2; ++m) {
      const int elements = m == 0 ? 40 : 80;
      const FoldRun run = Fold(elements, linear);
      ExpectCompleteAndBalanced(run);
      loop[law][m] = LoopHeight(run);
      std::printf("%8d %9s %10.3f %8d %12.3f %10.3f\n",
                  elements,
                  linear ? "linear" : "nonlinear",
                  loop[law][m],
                  run.summary.steps,
                  run.summary.max_curvature / 100,
                  run.summary.total_s);
      if (!linear) {
        // The fold stays inside the range the law was fitted over (2.5 1/cm):
        // measured 1.02 1/cm at the loop's crown.
        EXPECT_LT(run.summary.max_curvature, run.valid_to);
        EXPECT_EQ(run.summary.bending_valid_to, run.valid_to);
      }
    }
    // "Essentially converged for 40 elements" (paper): measured 0.8 % (nonlinear), 0.1 % (linear).
    EXPECT_NEAR(loop[law][0], loop[law][1], 0.01 * loop[law][1]);
  }
  // Around the crown's curvature (~1 1/cm) the cotton law is softer than its
  // Kawabata B (secant M/K = 0.562 gf·cm²/cm at 1 1/cm against 0.589), so
  // its loop is lower: measured 2.27 against 2.55 cm.
  EXPECT_LT(loop[0][1], loop[1][1]);
}

}  // namespace
}  // namespace drape
