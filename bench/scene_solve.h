// A whole scene solved end to end as a benchmark, with the counters the
// performance report quotes: steps and Newton iterations (total and per
// stage) and the factorisation's share of the time.
#pragma once

#include <benchmark/benchmark.h>

#include "core/solve/shell_solver.h"

namespace drape {

inline void SolveSceneForBenchmark(benchmark::State& bench, const Scene& scene) {
  SolveSummary summary;
  for (auto _ : bench) {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    summary = solver.Solve({});
  }
  if (!summary.IsComplete()) bench.SkipWithError(summary.message.c_str());
  bench.counters["steps"] = summary.steps;
  bench.counters["iterations"] = summary.iterations;
  bench.counters["factorization_share"] = summary.factorization_s / summary.total_s;
  for (const auto& st : summary.stages) {
    bench.counters[st.name + "_steps"] = st.steps;
    bench.counters[st.name + "_iterations"] = st.iterations;
  }
}

}  // namespace drape
