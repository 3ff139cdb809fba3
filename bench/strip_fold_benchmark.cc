// The paper's strip fold end to end, with its table (resources/scenes/
// strip-fold.json, issue 6) and without it (strip-fold-no-table.json, issue 5),
// with and without the γ = N_p/N acceleration (target: < 50 ms with
// acceleration). Counters: steps and Newton iterations per stage. (The table
// scene without acceleration is not here: its SW stage keeps Δλ₀ = 2.7e-6 on
// a strip that barely moves and needs > 100 000 steps; docs/performance.md.)
#include <benchmark/benchmark.h>

#include "core/io/scene_reader.h"
#include "scene_solve.h"

namespace drape {
namespace {

void BM_StripFold(benchmark::State& bench, const char* file, bool acceleration) {
  Scene scene = ReadScene(std::string(DRAPE_SOURCE_DIR) + "/resources/scenes/" + file);
  scene.solver.acceleration = acceleration;
  if (!acceleration) {
    scene.solver.max_steps = 100000;
    scene.stages[1].initial_increment = 0.0009;  // Table 3, without acceleration
  }
  SolveSceneForBenchmark(bench, scene);
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

}  // namespace
}  // namespace drape
