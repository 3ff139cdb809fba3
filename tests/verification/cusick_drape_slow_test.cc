// The Cusick drape test (docs/cusick.md) over a family of fabrics: a 30 cm
// specimen on 18 cm discs, h = 0.5 mm, E = 10 MPa, ν = 0.3, w = 2 N/m²,
// bending rigidity B = w c³ for a bending length c, a 0.5 mm smooth
// unevenness (seed 1). What the textile literature reports of every
// drapemeter (Cusick 1968; the standards' own tables): the drape
// coefficient rises with the bending length, and the nodes do not grow in
// number. And the coefficient of a stiff fabric does not depend on the
// mesh: two meshes within 0.02.
//
// Measured on 2 cores (1 thread), the drape coefficient and nodes:
//   c = 1.5 cm: 0.672, 4 (10.9 s);  2.5 cm: 0.839, 4 (2.3 s);  4 cm: 0.960, 4 (1.2 s);
//   4 cm on a 0.75 cm mesh: 0.970, 5 (2.5 s);
//   weft at a quarter of the warp (2.5 cm): 0.766, between 0.839 and 0.686
//   (the isotropic 1.57 cm), 11 s.
// Not asserted, because it does not hold yet (issue 36's notes): soft
// fabrics' coefficients move with the mesh as their node count does.
//   c = 2.5 cm on 1.25, 1 and 0.75 cm meshes: 0.796 (3 nodes), 0.839 (4), 0.890 (6);
//   c = 1.5 cm: 0.695 (4), 0.672 (4), 0.627 (4);
//   B and w both × 4 at c = 2.5 cm: 0.777 against 0.839 (E = 10 MPa).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/measure/drape_test_setup.h"
#include "core/solve/shell_solver.h"

namespace drape {
namespace {

constexpr double kWeight = 2.0;  // [N/m²]

// `weft_share`: the weft's rigidity as a share of the warp's (1: isotropic).
Scene Cusick(double bending_length, double mesh_size, double weft_share = 1) {
  Scene scene;
  scene.name = "Cusick test";
  scene.fabric.outline = DiskOutline{0.15, {0.0, 0.0}};
  scene.fabric.mesh.size = mesh_size;
  ImperfectionSpec unevenness;
  unevenness.amplitude = 5e-4;
  unevenness.seed = 1;
  scene.fabric.imperfection = unevenness;
  scene.material.thickness = 5e-4;
  scene.material.areal_weight = kWeight;
  scene.material.membrane = IsotropicMembrane{1e7, 0.3};
  const double rigidity = kWeight * std::pow(bending_length, 3);
  scene.material.bending.warp = LinearBending{rigidity};
  if (weft_share != 1) scene.material.bending.weft = LinearBending{weft_share * rigidity};
  scene.supports.push_back(
      {"discs", Selection{CircleSelection{{0, 0}, 0.09}, std::nullopt}, Fixity::kClamp});
  Stage hang;
  hang.name = "hang";
  hang.kind = StageKind::kGravity;
  scene.stages.push_back(hang);
  return scene;
}

struct Drape {
  double coefficient = NAN;
  int nodes = -1;
};

// Solves the test to λ = 1 (stable at the end, or the test fails) and measures it.
Drape MeasureScene(const Scene& scene, double bending_length, double mesh_size) {
  const ShellModel model = BuildShellModel(scene);
  ShellSolver solver(scene, model, SolverOptions::FromScene(scene.solver));
  StepState last;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    last = s;
    return StepDecision::kContinue;
  }});
  EXPECT_TRUE(summary.IsComplete()) << "c = " << bending_length << ": " << summary.message;
  EXPECT_EQ(last.negative_pivots, 0);
  const DrapeMeasurement m =
      MeasureDrape(last.state.positions, model.mesh.quads, DrapeTestFor(scene, model.mesh, {}, {}));
  std::printf("c = %.1f cm, mesh %.2f cm: DC %.4f, %zu nodes\n",
              bending_length * 100,
              mesh_size * 100,
              m.drape_coefficient,
              m.nodes.size());
  return {m.drape_coefficient, static_cast<int>(m.nodes.size())};
}

Drape Measure(double bending_length, double mesh_size, double weft_share = 1) {
  return MeasureScene(Cusick(bending_length, mesh_size, weft_share), bending_length, mesh_size);
}

TEST(CusickDrape, TheCoefficientRisesAndTheNodesDoNotWithTheBendingLength) {
  std::vector<Drape> family;
  for (double c : {0.015, 0.025, 0.04}) family.push_back(Measure(c, 0.01));
  for (size_t k = 1; k < family.size(); ++k) {
    EXPECT_GT(family[k].coefficient, family[k - 1].coefficient + 0.05) << k;
    EXPECT_LE(family[k].nodes, family[k - 1].nodes) << k;
  }
  for (const Drape& d : family) {
    EXPECT_GT(d.coefficient, 0);
    EXPECT_LT(d.coefficient, 1);
    EXPECT_GE(d.nodes, 3);  // a hanging specimen folds, into 3 to 10 nodes in any lab
  }
}

// The test's dimensionless groups are B/(w R³), E h/(w R) and 2HB/(w R²)
// (R the specimen's radius): scaling the weight, the bending rigidity, the
// membrane and the hysteresis by one factor is the same test, and so is its
// drape coefficient. (B and w alone are not enough: the membrane's E h/(w R)
// moves DC, docs/cusick.md "Limits".)
TEST(CusickDrape, ScalingEveryForceOfTheTestLeavesItsCoefficient) {
  Scene scene = Cusick(0.025, 0.01);
  scene.material.bending.warp_hysteresis.width = kWeight * 0.025 * 0.025 / 4;
  const Drape once = MeasureScene(scene, 0.025, 0.01);
  scene.material.areal_weight *= 4;
  std::get<LinearBending>(scene.material.bending.warp).rigidity.value() *= 4;
  std::get<IsotropicMembrane>(scene.material.membrane).youngs_modulus *= 4;
  scene.material.bending.warp_hysteresis.width *= 4;
  const Drape scaled = MeasureScene(scene, 0.025, 0.01);
  EXPECT_NEAR(scaled.coefficient, once.coefficient, 0.01);
  EXPECT_EQ(scaled.nodes, once.nodes);
}

TEST(CusickDrape, AStiffFabricsCoefficientIsConvergedWithTheMesh) {
  const Drape coarse = Measure(0.04, 0.01), fine = Measure(0.04, 0.0075);
  EXPECT_NEAR(coarse.coefficient, fine.coefficient, 0.02);
}

// A twill-like fabric whose weft bends at a quarter of its warp's rigidity
// drapes between the isotropic fabric of its warp's rigidity and that of its
// weft's (the bending length of B/4 is c/4^⅓).
TEST(CusickDrape, AnAnisotropicFabricDrapesBetweenItsWarpAndItsWeft) {
  const Drape warp = Measure(0.025, 0.01);
  const Drape weft = Measure(0.025 * std::cbrt(0.25), 0.01);
  const Drape both = Measure(0.025, 0.01, 0.25);
  EXPECT_GT(both.coefficient, weft.coefficient);
  EXPECT_LT(both.coefficient, warp.coefficient);
}

// Matsudaira et al.'s cotton broadcloth (docs/validation.md §8) on an
// isotropic membrane meets, at λ = 0.0345, two rest states whose folds
// nearly meet: each snap at the limit load lands on the other's branch, and
// the path went round between them until its time ran out (about 100 snaps
// in 200 s). After two landings at one λ the path jumps on, a tenth of Δλ₀
// further, as a stalled path does (docs/snaps.md).
TEST(CusickDrape, APathThatSnapsBackAndForthAtOneLoadJumpsOn) {
  constexpr double kGf = 9.80665e-3;
  const double h = 0.497e-3, w = 12.38e-6 / 1e-4 * 9.80665, b = 0.118 * kGf * 1e-2;
  Scene scene = Cusick(0.02, 0.01);
  scene.material.thickness = h;
  scene.material.areal_weight = w;
  scene.material.membrane = IsotropicMembrane{9807 / h, 0.2};
  scene.material.bending.warp = LinearBending{b};
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  double reached = 0;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    reached = s.lambda;
    // 60 steps: without the jump the path goes round (two steps a turn).
    return s.lambda > 0.036 || s.step > 60 ? StepDecision::kStop : StepDecision::kContinue;
  }});
  int round = 0;
  double last_landing = NAN, stalled_at = NAN;
  for (const StabilityEvent& e : summary.stability_events) {
    if (e.kind != StabilityKind::kSnap) continue;
    if (e.trigger == SnapTrigger::kLimit && std::abs(e.lambda - 0.03452) < 1e-5) {
      ++round;
      last_landing = e.lambda;
    }
    if (e.trigger == SnapTrigger::kStalled && std::isnan(stalled_at)) stalled_at = e.lambda;
  }
  std::printf("%d snaps at λ = %.6f, then a jump at λ = %.6f; stopped at λ = %.4f\n",
              round,
              last_landing,
              stalled_at,
              reached);
  EXPECT_EQ(round, 2);
  EXPECT_NEAR(stalled_at, last_landing + 0.1 * 0.01, 1e-9);
  EXPECT_GT(reached, 0.036);
}

}  // namespace
}  // namespace drape
