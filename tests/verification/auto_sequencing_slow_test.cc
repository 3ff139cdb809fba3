// solver.sequencing: auto, the default, on a drape large enough to take it:
// a heavy cantilever strip of 100 × 26 = 2 600 elements (α = 32) follows its
// path on 50 × 13 (the factor 2, named in the note), lands in one step on the
// elastica (an ODE shot inside the test, support/heavy_elastica.h), and where
// the path on the scene's own mesh ends. Slow (5 s; under the sanitizers
// 170 s): the path on the fine mesh is the yardstick.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <string>

#include "core/model/sequencing_check.h"
#include "support/heavy_elastica.h"
#include "support/recorded_run.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

TEST(AutoSequencing, FollowsALargeStripsPathOnACoarserMeshToTheElastica) {
  const double alpha = 32;
  test::StripSpec spec;
  spec.width = 0.02;
  Scene scene = test::HeavyStrip(spec, alpha, 0.01);
  scene.fabric.mesh.elements = std::array<int, 2>{100, 26};
  const test::ElasticaEnd exact = test::SolveHeavyElastica(alpha);
  Eigen::Vector3d tips[2];
  const int sequencing[2] = {kAutoSequencing, 1};
  for (int k : {0, 1}) {
    scene.solver.sequencing = sequencing[k];
    const test::Outcome run = test::SolveRecorded(scene);
    ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
    tips[k] = test::Probe(run.steps.back(), "tip") / spec.length;
    EXPECT_LT(std::hypot(tips[k].x() - exact.x, tips[k].z() - exact.z), 0.005);
    if (k == 0) {
      EXPECT_EQ(run.steps.size(), 1u);
      ASSERT_FALSE(run.summary.notes.empty());
      EXPECT_NE(run.summary.notes.back().find(
                    "(solver.sequencing: auto chose 2): the path on 50 x 13 elements"),
                std::string::npos)
          << run.summary.notes.back();
    } else {
      EXPECT_GT(run.steps.size(), 1u);
    }
  }
  // Both end where Newton met ‖R‖/‖R₀‖ ≤ 1e-5 from different starts:
  // measured 1.1e-6 L apart.
  EXPECT_LT((tips[0] - tips[1]).norm(), 1e-5);
}

}  // namespace
}  // namespace drape
