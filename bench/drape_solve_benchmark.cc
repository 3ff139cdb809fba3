// The shell engine's solve loop on the block drape (resources/scenes/
// block-drape.json: a 10 × 10 in polyester sheet pinned at its four corners,
// sagging under its own weight) meshed with n × n elements:
//
//  - one Newton iteration split into its parts: assembly of the internal
//    force and tangent, numeric factorisation of the tangent, and the solve
//    of K Δq = −R. Argument (n, state): state 1 is the converged drape at
//    λ = 1 (solved once per size before the first benchmark needing it;
//    n ≤ 100), state 0 the flat reference state with the full weight applied
//    (used at n = 200, and at n = 100 for comparison);
//  - the whole drape at 100 × 100 solved end to end with the scene's own
//    solver settings under load control.
//
// Times are wall-clock (UseRealTime): assembly runs on OpenMP threads and the
// factorisation on BLAS threads. Set OMP_NUM_THREADS / OPENBLAS_NUM_THREADS to
// compare thread counts. Results and the machine are in docs/performance.md.
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_assembler.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "core/solve/solver_options.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

Scene BlockDrape(int n) {
  Scene scene = ReadScene(test::ScenesDir() / "block-drape.json");
  scene.fabric.mesh.elements = std::array<int, 2>{n, n};
  scene.stages.at(0).control = StepControl::kLoad;  // as measured since issue 4
  return scene;
}

DofMap MakeDofMap(const ShellModel& model) {
  DofMap dofs(model.NodeCount());
  for (const auto* group : {&model.supports, &model.grippers})
    for (const auto& held : *group)
      for (int node : held.nodes) dofs.FixNode(node, held.fixity);
  return dofs;
}

// The converged drape of each size, from whichever benchmark solved it first
// (BM_BlockDrape runs first, so the 100 × 100 drape is solved only once).
std::map<int, ShellState>& ConvergedDrapes() {
  static std::map<int, ShellState> states;
  return states;
}

const ShellState& ConvergedDrape(const Scene& scene, const ShellModel& model, int n) {
  auto& states = ConvergedDrapes();
  if (auto it = states.find(n); it != states.end()) return it->second;
  ShellSolver solver(scene, model, SolverOptions::FromScene(scene.solver));
  const SolveSummary summary = solver.Solve({});
  if (!summary.IsComplete())
    throw std::runtime_error("block drape " + std::to_string(n) +
                             "² did not converge: " + summary.message);
  return states[n] = solver.state();
}

// One size and state of the drape with its equilibrium system, assembled
// (with tangent) at the state; built once per process and shared by the
// benchmarks.
struct Fixture {
  Scene scene;
  ShellModel model;
  DofMap dofs;
  ShellState state;
  Eigen::VectorXd residual;  // R = F_int − W over the free DOFs at `state`
  std::unique_ptr<EquilibriumSystem> system;
  long nonzeros = 0;  // of the tangent's upper triangle over the free DOFs

  Fixture(int n, bool converged)
      : scene(BlockDrape(n)), model(BuildShellModel(scene)), dofs(MakeDofMap(model)) {
    state = converged ? ConvergedDrape(scene, model, n) : model.reference;
    nonzeros = ShellAssembler(model, dofs).Pattern().nonZeros();
    system = std::make_unique<EquilibriumSystem>(model, dofs);
    system->Assemble(state, /*with_tangent=*/true);
    residual = system->Residual(model.weight_load);
  }
};

Fixture& Get(int n, bool converged) {
  static std::map<std::pair<int, bool>, std::unique_ptr<Fixture>> cache;
  auto& slot = cache[{n, converged}];
  if (!slot) slot = std::make_unique<Fixture>(n, converged);
  return *slot;
}

void SetSizeCounters(benchmark::State& bench, const Fixture& f) {
  bench.counters["elements"] = f.model.mesh.ElementCount();
  bench.counters["dofs"] = f.dofs.FreeCount();
  bench.counters["nonzeros"] = static_cast<double>(f.nonzeros);
}

Fixture& FixtureOf(const benchmark::State& bench) {
  return Get(static_cast<int>(bench.range(0)), bench.range(1) != 0);
}

// Assembly of energy, internal force and tangent (one per Newton iteration).
void BM_Assemble(benchmark::State& bench) {
  Fixture& f = FixtureOf(bench);
  for (auto _ : bench) benchmark::DoNotOptimize(f.system->Assemble(f.state, true));
  SetSizeCounters(bench, f);
  bench.counters["colors"] = f.system->ColorCount();
}

// Assembly of energy and internal force only (the residual check).
void BM_AssembleResidual(benchmark::State& bench) {
  Fixture& f = FixtureOf(bench);
  for (auto _ : bench) benchmark::DoNotOptimize(f.system->Assemble(f.state, false));
  SetSizeCounters(bench, f);
}

// Numeric factorisation of the assembled tangent (symbolic analysis done once
// per model, outside).
void BM_Factorize(benchmark::State& bench) {
  Fixture& f = FixtureOf(bench);
  f.system->Assemble(f.state, true);
  FactorizationInfo info;
  for (auto _ : bench) {
    info = f.system->Factorize();
    benchmark::ClobberMemory();
  }
  SetSizeCounters(bench, f);
  bench.counters["ldlt"] = info.used_ldlt;
  bench.counters["negative_pivots"] = info.negative_pivots;
}

// K⁻¹(−R) with the factorisation.
void BM_Solve(benchmark::State& bench) {
  Fixture& f = FixtureOf(bench);
  f.system->Assemble(f.state, true);
  const FactorizationInfo info = f.system->Factorize();
  const Eigen::VectorXd rhs = -f.residual;
  for (auto _ : bench) benchmark::DoNotOptimize(f.system->Solve(rhs));
  SetSizeCounters(bench, f);
  bench.counters["ldlt"] = info.used_ldlt;
}

// One whole Newton iteration: assemble, residual, factorise, solve, update
// (on a copy of the state, so every iteration starts from the same point).
void BM_NewtonIteration(benchmark::State& bench) {
  Fixture& f = FixtureOf(bench);
  ShellState state = f.state;
  for (auto _ : bench) {
    f.system->Assemble(state, true);
    const Eigen::VectorXd r = f.system->Residual(f.model.weight_load);
    f.system->Factorize();
    ApplyIncrement(f.dofs.Expand(f.system->Solve(-r)), state);
    bench.PauseTiming();
    state = f.state;
    bench.ResumeTiming();
  }
  SetSizeCounters(bench, f);
}

// The whole 100 × 100 block drape: every load step and Newton iteration from
// the reference state to λ = 1 (model built outside the timing); second
// argument solver.sequencing (1: the path on this mesh; 5: on 20 × 20, then
// Newton here from its end).
void BM_BlockDrape(benchmark::State& bench) {
  const int n = static_cast<int>(bench.range(0));
  Scene scene = BlockDrape(n);
  scene.solver.sequencing = static_cast<int>(bench.range(1));
  const auto build_start = Clock::now();
  ShellModel model = BuildShellModel(scene);
  const double build_s = std::chrono::duration<double>(Clock::now() - build_start).count();
  ShellSolver solver(scene, std::move(model), SolverOptions::FromScene(scene.solver));
  SolveSummary summary;
  double assembly_s = 0, factorization_s = 0, solve_s = 0;
  for (auto _ : bench) {
    summary = solver.Solve({});
    if (!summary.IsComplete()) {
      bench.SkipWithError(summary.message.c_str());
      break;
    }
    ConvergedDrapes()[n] = solver.state();
    assembly_s += summary.assembly_s;
    factorization_s += summary.factorization_s;
    solve_s += summary.solve_s;
  }
  const double runs = static_cast<double>(bench.iterations());
  bench.counters["dofs"] = summary.free_dofs;
  bench.counters["steps"] = summary.steps;
  bench.counters["newton_iterations"] = summary.iterations;
  bench.counters["step_cuts"] = summary.step_cuts;
  bench.counters["factorizations"] = summary.factorizations;
  bench.counters["indefinite_factorizations"] = summary.indefinite_factorizations;
  bench.counters["threads"] = summary.threads_used;
  bench.counters["model_build_s"] = build_s;
  if (runs > 0) {
    bench.counters["assembly_s"] = assembly_s / runs;
    bench.counters["factorization_s"] = factorization_s / runs;
    bench.counters["solve_s"] = solve_s / runs;
    bench.counters["assembly_share"] = assembly_s / (assembly_s + factorization_s + solve_s);
  }
}

void PerIterationSizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"n", "converged"});
  for (int n : {20, 50, 100}) b->Args({n, 1});
  b->Args({100, 0});
  b->Args({200, 0});
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_BlockDrape)
    ->ArgNames({"n", "sequencing"})
    ->Args({100, 1})
    ->Args({100, 5})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Assemble)->Apply(PerIterationSizes);
BENCHMARK(BM_AssembleResidual)->Apply(PerIterationSizes);
BENCHMARK(BM_Factorize)->Apply(PerIterationSizes);
BENCHMARK(BM_Solve)->Apply(PerIterationSizes);
BENCHMARK(BM_NewtonIteration)->Apply(PerIterationSizes);

}  // namespace
}  // namespace drape
