// The seed paper's contact experiments (Eischen, Deng & Clapp, "Finite-element
// modeling and control of flexible fabric parts", IEEE CG&A 16(5), 1996),
// run with the linear and the cotton's nonlinear bending law and compared with
// the published numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

struct PaperRun {
  SolveSummary summary;
  StepState last;
  double weight = 0;
};

PaperRun Solve(const char* file) {
  const Scene scene = ReadScene(test::ScenesDir() / file);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  PaperRun run;
  run.summary = solver.Solve({[&](const StepState& step) {
    run.last = step;
    return StepDecision::kContinue;
  }});
  run.weight = solver.model().total_weight.norm();
  return run;
}

// Everything that holds the fabric, at rest, carries its weight.
void ExpectForceBalance(const PaperRun& run, double tolerance) {
  Eigen::Vector3d held = run.last.contact->force;
  for (const auto& r : run.last.reactions) held += r.value;
  EXPECT_NEAR(held.z(), run.weight, tolerance * run.weight);
  EXPECT_NEAR(held.head<2>().norm(), 0.0, tolerance * run.weight);
}

// Table 2 with the cotton's nonlinear law: (3.85, −3.85, −12.14) cm computed.
TEST(PaperContact, RodDrapeNonlinearCornerAAgainstTable2) {
  const PaperRun run = Solve("rod-drape-nonlinear.json");
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const Eigen::Vector3d a = 100 * run.last.probes.at(0).value;  // cm
  std::printf(
      "rod drape (nonlinear), corner A [cm]: ours (%.3f, %.3f, %.3f); Table 2 nonlinear (3.85, "
      "-3.85, -12.14), measured (3.47, -3.47, -12.25); largest curvature %.3f 1/cm\n",
      a.x(),
      a.y(),
      a.z(),
      run.summary.max_curvature / 100);
  EXPECT_NEAR(a.x(), -a.y(), 1e-6);
  // Measured: 0.002 cm in x, 0.03 cm in z (0.15 % of the side). The same
  // unpublished details as for the linear run leave us 0.1 cm.
  EXPECT_NEAR(a.x(), 3.85, 0.1);
  EXPECT_NEAR(a.z(), -12.14, 0.1);
  ExpectForceBalance(run, 1e-4);
}

// Table 2: corner A (10, −10, 0) cm of a 20 × 20 cm cotton twill square whose
// diagonal rests on a 2.5 cm rod: (2.83, −2.83, −12.57) cm computed with
// linear bending, (3.47, −3.47, −12.25) cm measured.
TEST(PaperContact, RodDrapeCornerAAgainstTable2) {
  const PaperRun run = Solve("rod-drape-linear.json");
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const Eigen::Vector3d a = 100 * run.last.probes.at(0).value;  // cm
  std::printf(
      "rod drape, corner A [cm]: ours (%.2f, %.2f, %.2f); Table 2 linear (2.83, -2.83, "
      "-12.57), measured (3.47, -3.47, -12.25); %d steps, %.2f s\n",
      a.x(),
      a.y(),
      a.z(),
      run.summary.steps,
      run.summary.total_s);
  // The drape is symmetric about the diagonal through A.
  EXPECT_NEAR(a.x(), -a.y(), 1e-6);
  // The paper's own linear solution used a coarser model of the contact and
  // an unpublished mesh and rod position (see the scene's description); we
  // ask for agreement within 0.3 cm, 1.5 % of the square's side. Measured:
  // 0.17 cm in x, 0.12 cm in z.
  EXPECT_NEAR(a.x(), 2.83, 0.3);
  EXPECT_NEAR(a.z(), -12.57, 0.3);
  ExpectForceBalance(run, 1e-4);  // the scene's tolerance is 1e-5 of ‖R₀‖
}

// Figs. 16–17: a square folded on its diagonal on a table; the paper reports
// the loop's height, 4.22 cm computed (nonlinear bending; 3.58 cm after its
// 18 % mesh correction) and 2.80 cm measured. Ours is the linear law, so the
// number is reported, not asserted; the run must complete with the table
// and the reactions carrying the weight.
TEST(PaperContact, DiagonalFoldNonlinearLoopHeight) {
  const PaperRun run = Solve("diagonal-fold.json");
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const double loop = 100 * run.last.state.positions.col(2).maxCoeff();
  std::printf(
      "diagonal fold, loop height (nonlinear bending): %.2f cm; paper 4.22 cm computed, 2.80 cm "
      "measured; largest curvature %.2f 1/cm; %d steps, %.2f s\n",
      loop,
      run.summary.max_curvature / 100,
      run.summary.steps,
      run.summary.total_s);
  // Same mesh and law as the paper; the pinned far corner and the arc's
  // height are our assumptions (see the scene). Measured 3.79 cm, 10 % below
  // the paper's computed 4.22 cm and between it and the 2.80 cm measured.
  EXPECT_NEAR(loop, 4.22, 0.5);
  ExpectForceBalance(run, 1e-4);
}

TEST(PaperContact, DiagonalFoldLoopHeight) {
  const PaperRun run = Solve("diagonal-fold-linear.json");
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const auto& x = run.last.state.positions;
  const double loop = 100 * x.col(2).maxCoeff();
  std::printf(
      "diagonal fold, loop height (midsurface above the table's top, linear bending): "
      "%.2f cm; paper 4.22 cm computed (nonlinear), 2.80 cm measured; %d steps, %.2f s\n",
      loop,
      run.summary.steps,
      run.summary.total_s);
  EXPECT_GT(loop, 0.5);  // a loop stands up, the sheet is not flattened
  ExpectForceBalance(run, 1e-4);
  EXPECT_LT(run.summary.max_penetration, 0.01 * 0.0489e-2);  // 1 % of h
}

}  // namespace
}  // namespace drape
