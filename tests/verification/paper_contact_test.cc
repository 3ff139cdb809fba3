// The seed paper's contact experiments (Eischen, Deng & Clapp, "Finite-element
// modeling and control of flexible fabric parts", IEEE CG&A 16(5), 1996),
// run with the linear and the cotton's nonlinear bending law and compared with
// the published numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "support/paper_run.h"

namespace drape {
namespace {

using test::ExpectForceBalance;
using test::PaperRun;

// Table 2 with the cotton's nonlinear law: (3.85, −3.85, −12.14) cm computed.
TEST(PaperContact, RodDrapeNonlinearCornerAAgainstTable2) {
  const PaperRun run = test::SolvePaperScene("rod-drape-nonlinear.json");
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
  const PaperRun run = test::SolvePaperScene("rod-drape-linear.json");
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

}  // namespace
}  // namespace drape
