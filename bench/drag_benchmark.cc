// The live drag's frame rate (core/solve/gripper_drag.h): one benchmark
// iteration is one frame of a gripper dragged up and down, 40 frames a
// sweep, from the end of the scene's run (solved once, outside the timing).
// `frames_per_second` is what the workbench can show at most; the issue
// asks for 10 Hz at 20 × 20, and aims at 30.
//
//   build/bench/drag_benchmark --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/solve/gripper_drag.h"
#include "core/solve/shell_solver.h"

namespace drape {
namespace {

struct DragCase {
  const char* scene;  // under the source tree
  const char* gripper;
  Eigen::Vector3d sweep;  // the drag's far end
};

const DragCase kCornerLift{"tests/data/corner-lift-20x20.json", "corner", {0, 0, 0.03}};
const DragCase kDiagonalFold{"resources/scenes/diagonal-fold.json", "corner", {0, 0, 0.02}};

void BM_DragFrame(benchmark::State& bench, const DragCase& c) {
  const Scene scene = ReadScene(std::string(DRAPE_SOURCE_DIR) + "/" + c.scene);
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  options.threads = static_cast<int>(bench.range(0));
  ShellSolver solver(scene, options);
  if (!solver.Solve({}).IsComplete()) {
    bench.SkipWithError("the scene's run did not complete");
    return;
  }
  DragSettings settings;
  GripperDrag drag(solver.BasisForDrag(c.gripper), settings);
  int frame = 0;
  double worst = 0, corrections = 0, factorizations = 0;
  // The mean hides how frames differ: most are alike, and one that lays
  // the corner back onto the sheet costs many; the median and the slowest
  // frame say what the hand sees.
  std::vector<double> seconds;
  for (auto _ : bench) {
    // Up in 40 frames, down in 40: a hand going to and fro.
    const int k = frame++ % 80;
    const double along = k < 40 ? (k + 1) / 40.0 : (79 - k) / 40.0;
    const DragFrame f = drag.MoveTo(along * c.sweep);
    worst = std::max(worst, f.residual_ratio);
    seconds.push_back(f.seconds);
    corrections += f.corrections;
    factorizations += f.factorizations;
  }
  bench.counters["frames_per_second"] =
      benchmark::Counter(static_cast<double>(frame), benchmark::Counter::kIsRate);
  bench.counters["corrections"] = corrections / frame;
  bench.counters["factorizations"] = factorizations / frame;
  bench.counters["worst_residual_ratio"] = worst;
  std::sort(seconds.begin(), seconds.end());
  bench.counters["median_frame_ms"] = 1e3 * seconds[seconds.size() / 2];
  bench.counters["slowest_frame_ms"] = 1e3 * seconds.back();
}

BENCHMARK_CAPTURE(BM_DragFrame, corner_lift_20x20, kCornerLift)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DragFrame, diagonal_fold_20x20, kDiagonalFold)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->UseRealTime();

}  // namespace
}  // namespace drape
