// Offscreen rendering (issue 8): one frame at 1280 × 720 (show a state and
// read the picture back) for 20 × 20 and 200 × 200 sheets, and the strip
// fold's animation exported end to end by `drape animate`. Needs a display:
//   xvfb-run -a build/bench/render_benchmark
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/strip_scene.h"
#include "ui/render/display.h"
#include "ui/render/frame_renderer.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// An n × n sheet, 20 × 20 cm, in a wavy state (so normals and colours vary).
void BM_RenderFrame(benchmark::State& bench) {
  if (!DisplayProblem().empty()) {
    bench.SkipWithError(DisplayProblem().c_str());
    return;
  }
  const int n = static_cast<int>(bench.range(0));
  const bool field = bench.range(1) != 0;
  test::StripSpec spec;
  spec.width = 0.2;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{n, n};
  scene.probes.clear();
  const ShellModel model = BuildShellModel(scene);
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i)
    state.positions(i, 2) =
        0.02 * std::sin(30 * state.positions(i, 0)) * std::cos(20 * state.positions(i, 1));
  RenderOptions options;
  if (field) options.field = FieldKind::kDisplacement;
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
  Frame frame;
  frame.state = &state;
  for (auto _ : bench) {
    renderer.Show(frame);
    benchmark::DoNotOptimize(renderer.CaptureRgb());
  }
  bench.counters["nodes"] = model.NodeCount();
}
BENCHMARK(BM_RenderFrame)
    ->Args({20, 0})
    ->Args({20, 1})
    ->Args({200, 0})
    ->Args({200, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);  // fixed, so that repetitions can be aggregated

// `drape run` of the strip fold once, then `drape animate` to MP4 at
// 1280 × 720, one frame per step: the whole command, process start included.
void BM_AnimateStripFold(benchmark::State& bench) {
  const fs::path dir = fs::temp_directory_path() / "drape-animate-bench";
  fs::remove_all(dir);
  const std::string cli = DRAPE_CLI;
  const std::string scene = std::string(DRAPE_SOURCE_DIR) + "/resources/scenes/strip-fold.json";
  if (std::system((cli + " run '" + scene + "' -o '" + (dir / "fold").string() + "' -q").c_str()) !=
      0) {
    bench.SkipWithError("the strip fold did not solve");
    return;
  }
  for (auto _ : bench) {
    const std::string command = cli + " animate '" + (dir / "fold").string() + "' -o '" +
                                (dir / "fold.mp4").string() + "' 2> /dev/null";
    if (std::system(command.c_str()) != 0) {
      bench.SkipWithError("drape animate failed");
      break;
    }
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_AnimateStripFold)->Unit(benchmark::kSecond)->Iterations(3)->UseRealTime();

}  // namespace
}  // namespace drape
