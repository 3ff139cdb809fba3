// Verification: a cantilever strip bending under its own weight against the
// heavy elastica ODE (support/heavy_elastica.h), solved as a boundary-value
// problem by shooting.
//
// Then Peirce's cantilever test (F. T. Peirce 1930, J. Textile Inst. 21
// T377; ASTM D1388): the bending length c = (EI/wb)^⅓ is L/2 when the chord
// from root to tip makes 41.5° with the horizontal, i.e. α = (L/c)³ = 8.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/solve/shell_solver.h"
#include "support/heavy_elastica.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

using test::ElasticaEnd;
using test::SolveHeavyElastica;

constexpr double kDegrees = 180.0 / std::numbers::pi;

// ---- the FE strip -----------------------------------------------------------

Eigen::Vector3d Probe(const StepState& step, const std::string& name) {
  for (const auto& p : step.probes)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no probe '" << name << "' in step " << step.step;
  return Eigen::Vector3d::Constant(NAN);
}

struct GravityRun {
  SolveSummary summary;
  Eigen::Vector3d tip = Eigen::Vector3d::Constant(NAN);   // at the last step [m]
  Eigen::Vector3d root = Eigen::Vector3d::Constant(NAN);  // [m]
  double lambda = 0;                                      // of the last step
  int max_iterations = 0;                                 // in any one step
};

GravityRun RunHeavyStrip(const test::StripSpec& spec, double alpha, double initial_increment) {
  Scene scene = test::HeavyStrip(spec, alpha, initial_increment);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  GravityRun run;
  run.summary = solver.Solve({[&](const StepState& s) {
    run.tip = Probe(s, "tip");
    run.root = Probe(s, "root");
    run.lambda = s.lambda;
    run.max_iterations = std::max(run.max_iterations, s.iterations);
    return StepDecision::kContinue;
  }});
  return run;
}

// Angle below the horizontal of the chord from root to tip [deg].
double ChordAngleDeg(double dx, double dz) {
  return std::atan2(-dz, dx) * kDegrees;
}

// ---- tests ------------------------------------------------------------------

TEST(HeavyElastica, OdeSolutionIsConvergedInSteps) {
  // RK4 with 2000 steps against 8000: the reference itself is exact to far
  // below the FE tolerances (measured ~1e-13 for α = 1 … 100).
  for (double alpha : {1.0, 10.0, 100.0}) {
    const ElasticaEnd coarse = SolveHeavyElastica(alpha, 2000);
    const ElasticaEnd fine = SolveHeavyElastica(alpha, 8000);
    const double change = std::hypot(coarse.x - fine.x, coarse.z - fine.z);
    std::printf("α = %5.1f: k = θ'(0) = %.10f, tip (%.10f, %.10f), |Δtip| 2000→8000 steps = %.1e\n",
                alpha,
                coarse.root_curvature,
                coarse.x,
                coarse.z,
                change);
    EXPECT_LT(change, 1e-9);
  }
}

TEST(HeavyElastica, TipMatchesOdeFromSmallToLargeDeflection) {
  const test::StripSpec spec;  // 40 × 1 elements, ν = 0
  std::printf("%6s %9s %11s %11s %11s %11s %10s %6s %6s %5s %5s\n",
              "alpha",
              "dlambda0",
              "FE x/L",
              "FE z/L",
              "ODE x/L",
              "ODE z/L",
              "error/L",
              "steps",
              "iters",
              "max",
              "cuts");
  for (double alpha : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
    // The deflection saturates (the strip hangs nearly vertical) at large α;
    // start the larger loads with smaller steps.
    const double initial_increment = alpha <= 10 ? 0.05 : 0.01;
    const ElasticaEnd exact = SolveHeavyElastica(alpha);
    const GravityRun run = RunHeavyStrip(spec, alpha, initial_increment);
    EXPECT_TRUE(run.summary.IsComplete()) << "α = " << alpha << "\n" << run.summary.FullReport();
    EXPECT_DOUBLE_EQ(run.lambda, 1.0) << "α = " << alpha;
    const Eigen::Vector3d tip = run.tip / spec.length;
    const double error = std::hypot(tip.x() - exact.x, tip.z() - exact.z);
    std::printf("%6.1f %9.3f %11.6f %11.6f %11.6f %11.6f %10.3e %6d %6d %5d %5d\n",
                alpha,
                initial_increment,
                tip.x(),
                tip.z(),
                exact.x,
                exact.z,
                error,
                run.summary.steps,
                run.summary.iterations,
                run.max_iterations,
                run.summary.step_cuts);
    EXPECT_LT(error, 0.005) << "α = " << alpha;
  }
}

// Mesh sequencing (solver.sequencing): the path on 20 × 2 elements, then
// Newton on 40 × 4 from its interpolated end. One step, at the elastica as
// closely as the path on 40 × 4 itself, and the same state as that path's
// (the end of a drape does not depend on the path).
TEST(HeavyElastica, SequencedSolveEndsOnTheElastica) {
  const double alpha = 32;
  test::StripSpec spec;
  spec.width = 0.02;
  Scene scene = test::HeavyStrip(spec, alpha, 0.01);
  scene.fabric.mesh.elements = std::array<int, 2>{40, 4};
  const ElasticaEnd exact = SolveHeavyElastica(alpha);
  Eigen::Vector3d tips[2];
  for (int sequencing : {1, 2}) {
    scene.solver.sequencing = sequencing;
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    int steps = 0;
    const SolveSummary summary = solver.Solve({[&](const StepState& s) {
      tips[sequencing - 1] = Probe(s, "tip") / spec.length;
      ++steps;
      return StepDecision::kContinue;
    }});
    ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
    const Eigen::Vector3d& tip = tips[sequencing - 1];
    const double error = std::hypot(tip.x() - exact.x, tip.z() - exact.z);
    std::printf("α = 32, 40 × 4, sequencing %d: %d steps, %d factorisations, tip error %.3e L\n",
                sequencing,
                steps,
                summary.factorizations,
                error);
    EXPECT_LT(error, 0.005);
    if (sequencing == 2) {
      EXPECT_EQ(steps, 1);
      ASSERT_FALSE(summary.notes.empty());
      EXPECT_NE(summary.notes.back().find("the path on 20 x 2 elements"), std::string::npos)
          << summary.notes.back();
    }
  }
  EXPECT_LT((tips[1] - tips[0]).norm(), 1e-6);
}

TEST(HeavyElastica, PeirceCantileverChordAngleAtBendingLengthHalfTheStrip) {
  // c = L/2 ⇔ α = (L/c)³ = 8.
  const double alpha = 8.0;
  const ElasticaEnd exact = SolveHeavyElastica(alpha);
  const double ode_chord = ChordAngleDeg(exact.x, exact.z);

  const test::StripSpec spec;
  const GravityRun run = RunHeavyStrip(spec, alpha, 0.05);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const Eigen::Vector3d chord = run.tip - run.root;
  const double fe_chord = ChordAngleDeg(chord.x(), chord.z());

  // Exact heavy elastica at α = 8 (RK4, 2000 and 8000 steps agree): tip
  // (0.724425, −0.640631) L, tip slope 53.865°, chord 41.4873°: Peirce's
  // 41.5° is the exact value to 0.013° (the exact chord reaches 41.5° at
  // α = 8.0042, c = 0.49991 L). His closed-form approximation
  // c = L (cos ½θ / 8 tan θ)^⅓ is what is off: it gives c = 0.5093 L at 41.5°
  // and puts c = L/2 at 42.94°. The loose bound below only guards the
  // reading of the test; FE against the ODE is the real check.
  std::printf(
      "α = 8 (c = L/2): chord angle FE %.4f°, ODE %.4f°, FE − ODE = %+.4f°; "
      "Peirce 41.5°, ODE − Peirce = %+.4f°\n",
      fe_chord,
      ode_chord,
      fe_chord - ode_chord,
      ode_chord - 41.5);
  EXPECT_NEAR(fe_chord, ode_chord, 0.2);
  EXPECT_NEAR(ode_chord, 41.5, 1.5);
}

}  // namespace
}  // namespace drape
