// The paper's strip fold end to end, with its table (resources/scenes/
// strip-fold.json, issue 6) and without it (strip-fold-no-table.json, issue 5),
// with and without the γ = N_p/N acceleration (target: < 50 ms with
// acceleration). Counters: steps and Newton iterations per stage.
#include <benchmark/benchmark.h>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"

namespace drape {
namespace {

void BM_StripFold(benchmark::State& bench, const char* file, bool acceleration) {
  Scene scene = ReadScene(std::string(DRAPE_SOURCE_DIR) + "/resources/scenes/" + file);
  scene.solver.acceleration = acceleration;
  if (!acceleration) {
    scene.solver.max_steps = 100000;
    scene.stages[1].initial_increment = 0.0009;  // Table 3, without acceleration
  }
  SolveSummary summary;
  for (auto _ : bench) {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    summary = solver.Solve({});
  }
  if (!summary.IsComplete()) bench.SkipWithError(summary.message.c_str());
  bench.counters["steps"] = summary.steps;
  bench.counters["iterations"] = summary.iterations;
  for (const auto& st : summary.stages) {
    bench.counters[st.name + "_steps"] = st.steps;
    bench.counters[st.name + "_iterations"] = st.iterations;
  }
}
BENCHMARK_CAPTURE(BM_StripFold, accelerated, "strip-fold-no-table.json", true)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);
BENCHMARK_CAPTURE(BM_StripFold, constant_arc_length, "strip-fold-no-table.json", false)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_StripFold, table_accelerated, "strip-fold.json", true)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);
BENCHMARK_CAPTURE(BM_StripFold, table_constant_arc_length, "strip-fold.json", false)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace drape
