// What telling stable equilibria from unstable ones costs (issue 15):
//
//  - BM_SceneBranching: shipped scenes without a bifurcation, solved with
//    solver.branching stable and fundamental side by side. Nothing bifurcates,
//    so the two must cost the same: the pivot count comes from the converged
//    tangent's factorisation, which the next step's predictor reuses.
//  - BM_RoundOffLevel against BM_Assemble and BM_Factorize on the block
//    drape's converged tangent: the round-off floor that every Newton
//    iteration now evaluates, next to the iteration's own parts.
//  - BM_BranchSwitch: runs that pass one bifurcation onto a stable branch,
//    with the switch's cost (locating it, the critical mode, the step onto
//    the branch) as counters: switch_s, switch_iterations and its share of
//    the run.
//
// Results and the machine are in docs/performance.md.
#include <benchmark/benchmark.h>

#include <array>
#include <string>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

const char* const kQuietScenes[] = {"block-drape.json",
                                    "rod-drape-linear.json",
                                    "strip-convergence-80.json",
                                    "strip-fold-no-table.json"};

void BM_SceneBranching(benchmark::State& bench) {
  Scene scene = ReadScene(test::ScenesDir() / kQuietScenes[bench.range(0)]);
  scene.solver.branching = bench.range(1) ? Branching::kStable : Branching::kFundamental;
  SolveSummary summary;
  for (auto _ : bench) {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    summary = solver.Solve({});
  }
  if (!summary.IsComplete()) bench.SkipWithError(summary.message.c_str());
  if (!summary.stability_events.empty()) bench.SkipWithError("the scene has a stability event");
  bench.SetLabel(std::string(kQuietScenes[bench.range(0)]) +
                 (bench.range(1) ? " stable" : " fundamental"));
  bench.counters["steps"] = summary.steps;
  bench.counters["iterations"] = summary.iterations;
  bench.counters["factorizations"] = summary.factorizations;
}
BENCHMARK(BM_SceneBranching)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The block drape's converged tangent at n × n, assembled once.
struct Drape {
  Scene scene;
  ShellModel model;
  DofMap dofs;
  ShellState state;
};

Drape ConvergedDrape(int n) {
  Scene scene = ReadScene(test::ScenesDir() / "block-drape.json");
  scene.fabric.mesh.elements = std::array<int, 2>{n, n};
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  solver.Solve({});
  ShellModel model = BuildShellModel(scene);
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  return {scene, std::move(model), dofs, solver.state()};
}

void BM_RoundOffLevel(benchmark::State& bench) {
  const Drape d = ConvergedDrape(static_cast<int>(bench.range(0)));
  EquilibriumSystem system(d.model, d.dofs);
  system.Assemble(d.state, true);
  for (auto _ : bench) benchmark::DoNotOptimize(system.RoundOffLevel(d.state));
}
BENCHMARK(BM_RoundOffLevel)->Arg(20)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_Assemble(benchmark::State& bench) {
  const Drape d = ConvergedDrape(static_cast<int>(bench.range(0)));
  EquilibriumSystem system(d.model, d.dofs);
  for (auto _ : bench) benchmark::DoNotOptimize(system.Assemble(d.state, true));
}
BENCHMARK(BM_Assemble)->Arg(20)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Factorize(benchmark::State& bench) {
  const Drape d = ConvergedDrape(static_cast<int>(bench.range(0)));
  EquilibriumSystem system(d.model, d.dofs);
  int k = 0;
  for (auto _ : bench) {
    bench.PauseTiming();
    // The converged and the reference tangent in turn, so the system never
    // reuses the factor it holds.
    system.Assemble(++k % 2 ? d.state : d.model.reference, true);
    bench.ResumeTiming();
    benchmark::DoNotOptimize(system.Factorize());
  }
}
BENCHMARK(BM_Factorize)->Arg(20)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

// A strip pushed in by a gripper (80 × 1, clamped or pinned, first step far
// past Euler's load), and a 20 × 20 sheet pushed in its plane.
Scene Pushed(int which) {
  Scene scene;
  scene.name = "pushed";
  const bool sheet = which == 2;
  const double l = 0.2, b = sheet ? 0.2 : 0.01;
  scene.fabric.outline = RectangleOutline{{l, b}, {0.0, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{sheet ? 20 : 80, sheet ? 20 : 1};
  scene.material.thickness = 5e-4;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{sheet ? 5e6 : 1e8, sheet ? 0.3 : 0.0};
  scene.material.bending.warp = LinearBending{};
  const Fixity fix = which == 0 ? Fixity::kClamp : Fixity::kPosition;
  scene.supports.push_back({"left", Selection{EdgeSelection{Side::kLeft}, {}}, fix});
  scene.grippers.push_back({"right", Selection{EdgeSelection{Side::kRight}, {}}, fix});
  Stage push;
  push.name = "push";
  push.kind = StageKind::kMove;
  push.moves.push_back({"right", LinePath{{-(sheet ? 0.1 : 0.6) * l, 0.0, 0.0}}, {}});
  scene.stages.push_back(push);
  return scene;
}

void BM_BranchSwitch(benchmark::State& bench) {
  const Scene scene = Pushed(static_cast<int>(bench.range(0)));
  SolveSummary summary;
  for (auto _ : bench) {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    summary = solver.Solve({});
  }
  if (!summary.IsComplete()) bench.SkipWithError(summary.message.c_str());
  if (summary.branch_switches != 1) bench.SkipWithError("expected one branch switch");
  const char* labels[] = {"clamped strip 80x1", "pinned strip 80x1", "sheet 20x20"};
  bench.SetLabel(labels[bench.range(0)]);
  for (const auto& e : summary.stability_events)
    if (e.branch == Branch::kStable) {
      bench.counters["switch_s"] = e.switch_s;
      bench.counters["switch_iterations"] = e.switch_iterations;
      bench.counters["switch_share"] = e.switch_s / summary.total_s;
    }
  bench.counters["steps"] = summary.steps;
  bench.counters["iterations"] = summary.iterations;
}
BENCHMARK(BM_BranchSwitch)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace drape
