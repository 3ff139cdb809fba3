// Drape-tester specimens (the Cusick drape test, BS 5058 / ISO 9073-9): a
// circular specimen clamped between discs at its centre hangs under its
// weight. Real fabrics (weights 10–16 mg/cm², bending lengths c = (B/w)^⅓
// of 1.2–2.2 cm) on the two standard geometries, a 25.4 cm specimen on a
// 12.7 cm disc and a 30 cm one on 18 cm. Hanging, the specimen buckles into
// nodes: its flat path bifurcates and, with no stable branch from there, the
// part snaps to a node pattern (issue 34: before snaps, 5 of 8 such runs
// stopped). Each run must converge under `stable` branching with 0 negative
// pivots at every step, λ never falling, its lowest point below half the
// overhang (a cantilever of the overhang's length, 3–5 bending lengths, hangs
// most of its length down). Measured on 2 cores, the four combinations of
// the two geometries and c = 1.2, 2.2 cm (w = 1.0, 1.6, 1.6, 1.0 N/m²): 6.0,
// 1.5, 12.1 and 2.7 s with 1, 0, 1 (and a branch switch) and 0 snaps; the
// test runs the first and the last (9 s together).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/fe/shell_model.h"
#include "core/model/fabric_mesh.h"
#include "core/solve/shell_solver.h"

namespace drape {
namespace {

struct Specimen {
  double radius = 0;          // [m]
  double disc_radius = 0;     // [m]
  double bending_length = 0;  // c [m]
  double weight = 0;          // w [N/m²]
};

Scene SpecimenScene(const Specimen& s) {
  Scene scene;
  scene.name = "drape-tester specimen";
  scene.fabric.outline = DiskOutline{s.radius, {0.0, 0.0}};
  scene.fabric.mesh.size = 0.01;
  scene.material.thickness = 4e-4;
  scene.material.areal_weight = s.weight;
  scene.material.membrane = IsotropicMembrane{5e6, 0.3};
  scene.material.bending.warp =
      LinearBending{s.weight * s.bending_length * s.bending_length * s.bending_length};
  Stage stage;
  stage.name = "drape";
  stage.kind = StageKind::kGravity;
  stage.initial_increment = 0.05;
  scene.stages.push_back(stage);
  return scene;
}

// The nodes the discs clamp: every node within the disc's radius.
NodesSelection Disc(const Mesh& mesh, double radius) {
  NodesSelection disc;
  for (int i = 0; i < mesh.positions.rows(); ++i)
    if (mesh.positions.row(i).head<2>().norm() <= radius * (1 + 1e-9)) disc.nodes.push_back(i);
  return disc;
}

class DrapeTester : public testing::TestWithParam<Specimen> {};

TEST_P(DrapeTester, TheSpecimenDrapesStably) {
  const Specimen& s = GetParam();
  Scene scene = SpecimenScene(s);
  const Mesh mesh = MeshFabric(scene.fabric);
  scene.supports.push_back({"discs", Selection{Disc(mesh, s.disc_radius), {}}, Fixity::kClamp});
  ShellSolver solver(scene, BuildShellModel(scene, mesh), SolverOptions::FromScene(scene.solver));
  double last_lambda = 0, lowest = NAN;
  int unstable = 0, falls = 0;
  const auto start = std::chrono::steady_clock::now();
  const SolveSummary summary = solver.Solve({[&](const StepState& step) {
    unstable += step.negative_pivots > 0;
    falls += step.lambda < last_lambda;
    last_lambda = step.lambda;
    lowest = step.state.positions.col(2).minCoeff();
    return StepDecision::kContinue;
  }});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.1f cm on %.1f cm, c = %.1f cm: %s (%.1f s); lowest point %.2f cm\n",
              200 * s.radius,
              200 * s.disc_radius,
              100 * s.bending_length,
              summary.BriefReport().c_str(),
              seconds,
              100 * lowest);
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  EXPECT_EQ(unstable, 0);
  EXPECT_EQ(falls, 0);
  EXPECT_LT(lowest, -0.5 * (s.radius - s.disc_radius));
}

INSTANTIATE_TEST_SUITE_P(Specimens,
                         DrapeTester,
                         testing::Values(Specimen{0.127, 0.0635, 0.012, 1.0},
                                         Specimen{0.15, 0.09, 0.022, 1.0}),
                         [](const testing::TestParamInfo<Specimen>& info) {
                           const Specimen& s = info.param;
                           return "d" + std::to_string(std::lround(2000 * s.radius)) + "mm_c" +
                                  std::to_string(std::lround(1000 * s.bending_length)) + "mm";
                         });

}  // namespace
}  // namespace drape
