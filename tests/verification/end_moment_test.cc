// Verification: a cantilever strip under an end moment bends into a circular
// arc of radius R = EI/M (the bending moment is M all along the strip), so the
// tip of a strip of length L sits at
//   x = R sin(L/R),  z = −R (1 − cos(L/R)).
// M = 2πEI/L rolls the strip into a closed circle (tip back at the root) and
// M = πEI/L into a half circle (tip at x = 0, z = −2L/π). Every converged load
// step λ must lie on the circle of radius EI/(λM). The exact answer is
// independent of the mesh; 40 × 1 elements, ν = 0 (beam and plate agree).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector3d Probe(const StepState& step, const std::string& name) {
  for (const auto& p : step.probes)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no probe '" << name << "' in step " << step.step;
  return Eigen::Vector3d::Constant(NAN);
}

// Tip of a strip of length L bent into an arc of radius R (downward, in x-z).
Eigen::Vector3d ArcTip(double length, double radius) {
  return {radius * std::sin(length / radius), 0.0, -radius * (1 - std::cos(length / radius))};
}

struct MomentRun {
  SolveSummary summary;
  std::vector<StepState> steps;
};

// Ramps a tip moment `moment` about +y (tip toward −z) from 0 to 1 under the
// default branching (stable). The moment about the tip edge does work through
// the edge's twist, with its load stiffness (core/fe/edge_moments.h), so the
// tangent's pivots are the strip's own: 0 at every step. (As a fixed vector
// without load stiffness it gave one negative pivot past about 290° of
// roll-up.) The benchmark has no contact: at closure the tip meets the root,
// which the fabric's self-contact would hold a thickness away.
MomentRun RunEndMoment(const test::StripSpec& spec, double moment) {
  Scene scene = test::TipLoadedStrip(spec, {0, 0, 0}, {0, moment, 0});
  scene.contact = Contact{.self = false};
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  MomentRun run;
  run.summary = solver.Solve({[&](const StepState& s) {
    run.steps.push_back(s);
    return StepDecision::kContinue;
  }});
  std::printf("%s\n", run.summary.BriefReport().c_str());
  return run;
}

// The run completed and its last step carries the whole moment.
bool ReachedFullMoment(const MomentRun& run) {
  return run.summary.IsComplete() && !run.steps.empty() && run.steps.back().lambda == 1.0;
}

// Checks and prints every converged step against the arc of radius EI/(λM);
// returns the largest tip error over L.
double CheckStepsOnArc(const test::StripSpec& spec, double moment, const MomentRun& run) {
  const double ei = test::StripBendingStiffness(spec);
  const double length = spec.length;
  double worst = 0;
  std::printf("%6s %5s %5s %11s %11s %11s %11s %10s\n",
              "lambda",
              "iters",
              "L/R",
              "FE x/L",
              "FE z/L",
              "exact x/L",
              "exact z/L",
              "error/L");
  for (const auto& step : run.steps) {
    const double radius = ei / (step.lambda * moment);
    const Eigen::Vector3d tip = Probe(step, "tip");
    const Eigen::Vector3d exact = ArcTip(length, radius);
    const double error = (tip - exact).norm() / length;
    worst = std::max(worst, error);
    std::printf("%6.4f %5d %5.3f %11.6f %11.6f %11.6f %11.6f %10.3e\n",
                step.lambda,
                step.iterations,
                length / radius,
                tip.x() / length,
                tip.z() / length,
                exact.x() / length,
                exact.z() / length,
                error);
    EXPECT_LT(error, 0.01) << "step " << step.step << " at λ = " << step.lambda;
    EXPECT_EQ(step.negative_pivots, 0) << "step " << step.step << " at λ = " << step.lambda;
  }
  return worst;
}

// The closure gap |tip − root| is the discretisation's error (the exact
// circle closes): 40 elements put the tip 4.19e-3 L short of the root, 160
// elements 2.98e-4 L (the error falls about as h²: 14 times for 4).
TEST(EndMoment, FullMomentRollsStripIntoClosedCircle) {
  for (const int elements : {40, 160}) {
    const test::StripSpec spec = test::StripOf(elements);
    const double moment = 2 * kPi * test::StripBendingStiffness(spec) / spec.length;
    const MomentRun run = RunEndMoment(spec, moment);
    ASSERT_TRUE(ReachedFullMoment(run)) << run.summary.FullReport();

    const double worst = CheckStepsOnArc(spec, moment, run);
    const Eigen::Vector3d tip = Probe(run.steps.back(), "tip");
    const Eigen::Vector3d root = Probe(run.steps.back(), "root");
    const double gap = (tip - root).norm() / spec.length;
    std::printf(
        "closed circle (M = 2πEI/L), %d elements: |tip − root|/L = %.3e (exact 0), worst step "
        "%.3e, %d steps, %d iterations, %d cut-backs\n",
        elements,
        gap,
        worst,
        run.summary.steps,
        run.summary.iterations,
        run.summary.step_cuts);
    EXPECT_LT(gap, elements == 40 ? 5e-3 : 1e-3);
  }
}

TEST(EndMoment, HalfMomentBendsStripIntoHalfCircle) {
  const test::StripSpec spec;
  const double moment = kPi * test::StripBendingStiffness(spec) / spec.length;
  const MomentRun run = RunEndMoment(spec, moment);
  ASSERT_TRUE(ReachedFullMoment(run)) << run.summary.FullReport();

  const double worst = CheckStepsOnArc(spec, moment, run);
  // R = EI/M = L/π: the tip is straight below the root, by the diameter 2R.
  const Eigen::Vector3d tip = Probe(run.steps.back(), "tip");
  const Eigen::Vector3d exact(0.0, 0.0, -2 * spec.length / kPi);
  const double error = (tip - exact).norm() / spec.length;
  std::printf(
      "half circle (M = πEI/L): tip/L = (%.6f, %.6f), exact (0, %.6f), error/L = %.3e, "
      "worst step %.3e, %d steps, %d iterations, %d cut-backs\n",
      tip.x() / spec.length,
      tip.z() / spec.length,
      exact.z() / spec.length,
      error,
      worst,
      run.summary.steps,
      run.summary.iterations,
      run.summary.step_cuts);
  EXPECT_LT(error, 0.01);
}

}  // namespace
}  // namespace drape
