// Honest convergence: a step converges when ‖R‖/‖R₀‖ meets the tolerance or
// ‖R‖ is at the round-off floor of the arithmetic; a Newton iteration whose
// corrections stop with the residual above both is a stall, never
// "converged".
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/dof_map.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/random_element.h"
#include "support/test_paths.h"

namespace drape {
namespace {

NewtonSettings Settings() {
  NewtonSettings s;
  s.tolerance = 1e-6;
  s.round_off_factor = 10;
  s.stall_correction = 1e-9;
  return s;
}

TEST(NewtonJudge, ToleranceAndRoundOffConverge) {
  const NewtonSettings s = Settings();
  EXPECT_EQ(s.Judge({1.0, 1e-6}, 1.0, 0.0, 1.0), Convergence::kTolerance);
  // ‖R‖ = 1e-12 N at a round-off level of 2e-13 N: at the floor (10×).
  EXPECT_EQ(s.Judge({1.0, 1e-3}, 1e-12, 2e-13, 1.0), Convergence::kRoundOff);
  EXPECT_EQ(s.Judge({1.0, 1e-3}, 1e-12, 0.9e-14, 1.0), Convergence::kNotYet);
}

TEST(NewtonJudge, TinyCorrectionsWithAFlatResidualAreAStallNotConvergence) {
  const NewtonSettings s = Settings();
  // The corrections have stopped (1e-12 m) and the residual no longer halves.
  EXPECT_EQ(s.Judge({1.0, 1e-3, 0.8e-3}, 1e-6, 1e-15, 1e-12), Convergence::kStalled);
  // The same correction while the residual still halves: progress.
  EXPECT_EQ(s.Judge({1.0, 1e-3, 0.4e-3}, 1e-6, 1e-15, 1e-12), Convergence::kNotYet);
  // A ratio of √tolerance (1e-3) is not converged, whatever the corrections do.
  EXPECT_NE(s.Judge({1.0, 1e-3}, 1e-6, 1e-15, 1e-12), Convergence::kTolerance);
  // Large corrections: keep iterating.
  EXPECT_EQ(s.Judge({1.0, 1e-3, 1e-3}, 1e-6, 1e-15, 1e-3), Convergence::kNotYet);
}

struct DrapeAtRest {
  Scene scene;
  ShellModel model;
  DofMap dofs;
  ShellState state;
};

DrapeAtRest ConvergedBlockDrape(int n) {
  Scene scene = ReadScene(test::ScenesDir() / "block-drape.json");
  scene.fabric.mesh.elements = std::array<int, 2>{n, n};
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  EXPECT_TRUE(solver.Solve({}).IsComplete());
  ShellModel model = BuildShellModel(scene);
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  return {scene, std::move(model), dofs, solver.state()};
}

// The round-off level is what it claims: rounding every coordinate of a
// converged state by about one unit in the last place changes the residual
// by about that much (measured here by doing it).
TEST(RoundOffLevel, MatchesTheResidualChangeFromRoundingTheState) {
  DrapeAtRest d = ConvergedBlockDrape(10);
  EquilibriumSystem system(d.model, d.dofs);
  system.Assemble(d.state, true);
  const Eigen::VectorXd r0 = system.Residual(d.model.weight_load);
  const double level = system.RoundOffLevel(d.state);
  const double eps = std::numeric_limits<double>::epsilon();
  const double coordinate = d.state.positions.cwiseAbs().maxCoeff();
  SplitMix64 rng(4);
  double sum = 0;
  const int trials = 8;
  for (int t = 0; t < trials; ++t) {
    ShellState rounded = d.state;
    Eigen::VectorXd kick = Eigen::VectorXd::Zero(d.dofs.FreeCount());
    for (int dof = 0; dof < d.dofs.DofCount(); ++dof) {
      const int f = d.dofs.Free(dof);
      if (f < 0) continue;
      const double scale = dof % kDofsPerNode < 3 ? eps * coordinate : eps;
      kick(f) = scale * (rng.NextUniform() < 0.5 ? -1.0 : 1.0);
    }
    ApplyIncrement(d.dofs.Expand(kick), rounded);
    system.Assemble(rounded, false);
    sum += (system.Residual(d.model.weight_load) - r0).squaredNorm();
  }
  const double measured = std::sqrt(sum / trials);
  std::printf(
      "round-off level %.3e N, residual change from rounding the state %.3e N\n", level, measured);
  EXPECT_GT(measured, level / 4);
  EXPECT_LT(measured, level * 4);
}

// An external force that wobbles with the state by 1e-7 of the weight: no
// Newton iteration can bring the residual below that, and it is far above
// round-off, so the iteration must end as a stall.
TEST(NewtonStall, AResidualThatCannotFallIsAStallNotConverged) {
  DrapeAtRest d = ConvergedBlockDrape(10);
  EquilibriumSystem system(d.model, d.dofs);
  const double weight = d.model.weight_load.norm();
  auto wobbling = [&](const ShellState& s) {
    Eigen::VectorXd f = d.model.weight_load;
    // A deterministic function of the state with no useful derivative.
    const double phase = 1e9 * s.positions.sum();
    for (int i = 0; i < f.size(); i += kDofsPerNode)
      f(i + 2) += 1e-7 * weight * std::sin(phase + i);
    return f;
  };
  NewtonSettings settings;
  settings.tolerance = 1e-10;
  settings.relative_to_force_level = true;
  settings.stall_correction = 1e-8 * d.model.characteristic_length;
  settings.max_iterations = 30;
  ShellState state = d.state;
  const NewtonOutcome out = SolveEquilibrium(system, wobbling, settings, state, nullptr);
  std::printf("residuals:");
  for (double r : out.residuals) std::printf(" %.2e", r);
  std::printf("\n%s\n", out.reason.c_str());
  EXPECT_EQ(out.status, NewtonOutcome::Status::kStalled);
  EXPECT_EQ(out.convergence, Convergence::kStalled);
  EXPECT_GT(out.residuals.back(), settings.tolerance);
  EXPECT_NE(out.reason.find("stalled"), std::string::npos);
}

// The case: a 30 × 30 drape at tolerance 1e-9, under load control so
// that R₀ is exactly the weight the step added, Δλ‖W‖ over the free DOFs.
// Every step's residual is recomputed from the state it reports, with a
// system of its own: it meets the tolerance, or it is within the round-off
// floor and the step says so.
TEST(NewtonStall, EveryStepMeetsTheToleranceOrSaysItIsAtRoundOff) {
  Scene scene = ReadScene(test::ScenesDir() / "block-drape.json");
  scene.fabric.mesh.elements = std::array<int, 2>{30, 30};
  scene.stages[0].control = StepControl::kLoad;
  scene.solver.tolerance = 1e-9;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  std::vector<StepState> steps;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    steps.push_back(s);
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  const ShellModel& model = solver.model();
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  EquilibriumSystem system(model, dofs);
  const double weight = dofs.Restrict(model.weight_load).norm();
  int at_floor = 0;
  double lambda = 0;
  for (const StepState& s : steps) {
    system.Assemble(s.state, /*with_tangent=*/true);
    const double norm = system.Residual(s.lambda * model.weight_load).norm();
    const double added = (s.lambda - lambda) * weight;  // R₀
    lambda = s.lambda;
    if (s.convergence == Convergence::kTolerance) {
      EXPECT_LE(norm, 1e-9 * added * (1 + 1e-6)) << "step " << s.step;
    } else {
      EXPECT_EQ(s.convergence, Convergence::kRoundOff) << "step " << s.step;
      EXPECT_LE(norm, 10 * system.RoundOffLevel(s.state)) << "step " << s.step;
      ++at_floor;
    }
    std::printf("step %d: ‖R‖/R₀ = %.2e (%s)\n", s.step, norm / added, ToString(s.convergence));
  }
  std::printf("%zu steps, %d at the round-off floor\n", steps.size(), at_floor);
}

}  // namespace
}  // namespace drape
