// Accuracy presets (core/model/solver_preset.h): the mesh each solves, the
// same answer as the scene written out with the preset's values, and the
// order of their errors against the heavy elastica's ODE.
#include "core/model/solver_preset.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/solve/error_estimate.h"
#include "core/solve/shell_solver.h"
#include "support/heavy_elastica.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

struct Solved {
  bool complete = false;
  int elements = 0;
  Eigen::Vector3d tip = Eigen::Vector3d::Constant(NAN);
  std::vector<NamedVector> probes;
};

Solved Solve(const Scene& scene) {
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  Solved out;
  out.elements = solver.model().mesh.ElementCount();
  out.complete = solver
                     .Solve({[&](const StepState& s) {
                       out.probes = s.probes;
                       for (const auto& p : s.probes)
                         if (p.name == "tip") out.tip = p.value;
                       return StepDecision::kContinue;
                     }})
                     .IsComplete();
  return out;
}

TEST(ScaledMesh, ScalesEachDirectionOfMoreThanTwoElementsAndDividesASize) {
  MeshSpec counts;
  counts.elements = std::array<int, 2>{80, 2};
  EXPECT_EQ(ScaledMesh(counts, 2).elements, (std::array<int, 2>{160, 2}));
  EXPECT_EQ(ScaledMesh(counts, 0.5).elements, (std::array<int, 2>{40, 2}));
  counts.elements = std::array<int, 2>{15, 3};  // odd counts round half away from zero
  EXPECT_EQ(ScaledMesh(counts, 0.5).elements, (std::array<int, 2>{8, 2}));
  counts.elements = std::array<int, 2>{20, 20};
  EXPECT_EQ(ScaledMesh(counts, 1).elements, (std::array<int, 2>{20, 20}));
  MeshSpec size;
  size.size = 0.004;
  EXPECT_DOUBLE_EQ(*ScaledMesh(size, 2).size, 0.002);
  EXPECT_DOUBLE_EQ(*ScaledMesh(size, 0.5).size, 0.008);
}

TEST(SolverPreset, SetsItsValuesAndKeepsEveryOtherSetting) {
  SolverSettings base;
  base.max_steps = 123;
  base.branching = Branching::kFundamental;
  for (const PresetDefinition& p : PresetDefinitions()) {
    const SolverSettings s = WithPreset(base, p.preset);
    EXPECT_EQ(PresetNamed(p.name), p.preset);
    EXPECT_EQ(std::string(ToString(p.preset)), p.name);
    EXPECT_EQ(s.preset, p.preset);
    EXPECT_EQ(s.tolerance, p.tolerance);
    EXPECT_EQ(s.target_iterations, p.target_iterations);
    EXPECT_EQ(s.mesh_scale, p.mesh_scale);
    EXPECT_EQ(s.max_steps, 123);
    EXPECT_EQ(s.branching, Branching::kFundamental);
  }
  EXPECT_FALSE(PresetNamed("fast").has_value());
  // Finer and tighter from draft to accurate.
  const auto presets = PresetDefinitions();
  for (size_t i = 1; i < presets.size(); ++i) {
    EXPECT_LT(presets[i].tolerance, presets[i - 1].tolerance);
    EXPECT_GT(presets[i].mesh_scale, presets[i - 1].mesh_scale);
  }
}

// A preset is only a name for values: the run at `accurate` is the run of
// the scene written out with twice its elements, tolerance 1e-7 and N_p 6,
// to the last digit.
TEST(SolverPreset, RunsTheSceneWrittenOutWithItsValues) {
  test::StripSpec spec;
  spec.elements = 8;
  Scene preset = test::HeavyStrip(spec, 8.0);
  preset.solver = WithPreset(preset.solver, SolverPreset::kAccurate);
  Scene by_hand = test::HeavyStrip(spec, 8.0);
  by_hand.fabric.mesh.elements = std::array<int, 2>{16, 1};
  by_hand.solver.tolerance = 1e-7;
  by_hand.solver.target_iterations = 6;
  const Solved a = Solve(preset), b = Solve(by_hand);
  ASSERT_TRUE(a.complete && b.complete);
  EXPECT_EQ(a.elements, 16);
  EXPECT_EQ(a.tip, b.tip);
  // The estimate coarsens the mesh that was solved: 16, 8, 4 elements.
  const ErrorEstimate e = EstimateError(preset, SolverOptions::FromScene(preset.solver), a.probes);
  EXPECT_EQ(e.meshes[0], "16 x 1");
  EXPECT_EQ(e.meshes[1], "8 x 1");
  EXPECT_EQ(e.meshes[2], "4 x 1");
}

// The heavy elastica at α = 8 (ODE solved in the test) on a 16-element
// strip: each preset's tip error at most a third of the coarser one's (the
// mesh doubles and the element is second order: a quarter, measured 1.13e-3,
// 2.81e-4, 7.08e-5 m), and draft's within 1 % of the length — what "a quick
// look" promises.
TEST(SolverPreset, ErrorFallsFromDraftToAccurateOnTheHeavyElastica) {
  const double alpha = 8;
  const test::ElasticaEnd exact = test::SolveHeavyElastica(alpha);
  test::StripSpec spec;
  spec.elements = 16;
  double previous = INFINITY;
  for (const PresetDefinition& p : PresetDefinitions()) {
    Scene scene = test::HeavyStrip(spec, alpha);
    scene.solver = WithPreset(scene.solver, p.preset);
    const Solved s = Solve(scene);
    ASSERT_TRUE(s.complete) << p.name;
    EXPECT_EQ(s.elements, static_cast<int>(16 * p.mesh_scale)) << p.name;
    const double error =
        std::hypot(s.tip.x() - exact.x * spec.length, s.tip.z() - exact.z * spec.length);
    std::printf(
        "heavy elastica α = 8, %s: %d elements, tip error %.3e m\n", p.name, s.elements, error);
    EXPECT_LT(error, previous / 3) << p.name;
    EXPECT_LT(error, 0.01 * spec.length) << p.name;
    previous = error;
  }
}

}  // namespace
}  // namespace drape
