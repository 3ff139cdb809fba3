// The workbench while the solver streams a 100 × 100 drape (issue 9), and
// instant previews (issue 20, BM_Preview below). While streaming: how
// late the GUI thread's event loop answers (a 10 ms timer's lateness:
// target < 100 ms) and how many frames per second the viewport draws when
// redrawn continuously (target ≥ 30), 10 s of the run. Needs a display:
//   xvfb-run -a build/bench/workbench_benchmark
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "ui/render/display.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/preview_controller.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

QApplication* App() {
  static int argc = 1;
  static char name[] = "workbench_benchmark";
  static char* argv[] = {name, nullptr};
  static QApplication* app = [] {
    QSurfaceFormat::setDefaultFormat(VtkViewport::defaultFormat());
    return new QApplication(argc, argv);
  }();
  return app;
}

// The block drape (corners pinned, self-weight) on an n × n mesh.
std::string BlockDrape(int n) {
  std::ifstream in(std::string(DRAPE_SOURCE_DIR) + "/resources/scenes/block-drape.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["fabric"]["mesh"] = {{"elements", {n, n}}};
  const std::string file =
      (std::filesystem::temp_directory_path() / "drape-bench-drape.json").string();
  std::ofstream(file) << doc.dump();
  return file;
}

void BM_WorkbenchDuringRun(benchmark::State& bench) {
  if (!DisplayProblem().empty()) {
    bench.SkipWithError("no display: run under xvfb-run -a");
    return;
  }
  App();
  const int n = static_cast<int>(bench.range(0));
  const std::string scene = BlockDrape(n);
  for (auto _ : bench) {
    MainWindow window;
    window.resize(1280, 800);
    window.show();
    window.openScene(QString::fromStdString(scene));
    std::vector<double> lateness;  // [ms]
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0;
    QTimer tick;
    tick.setInterval(10);
    QObject::connect(&tick, &QTimer::timeout, [&] {
      const qint64 now = clock.elapsed();
      if (last > 0) lateness.push_back(std::max<qint64>(0, now - last - 10));
      last = now;
    });
    // The view redrawn as fast as it can (as while the user turns it): its
    // frame rate with the solver working on the other core.
    QTimer spin;
    spin.setInterval(0);
    QObject::connect(&spin, &QTimer::timeout, [&] { window.viewport()->requestRender(); });
    spin.start();
    const long long paints_before = window.viewport()->paints();
    int steps_at_start = 0;
    window.run();
    tick.start();
    QElapsedTimer run_clock;
    run_clock.start();
    while (run_clock.elapsed() < 10000 && window.isRunning())
      QApplication::processEvents(QEventLoop::AllEvents, 5);
    const double seconds = run_clock.elapsed() / 1000.0;
    const long long paints = window.viewport()->paints() - paints_before;
    const int steps = window.stepCount() - steps_at_start;
    window.stop();
    while (window.isRunning()) QApplication::processEvents(QEventLoop::AllEvents, 5);
    tick.stop();
    spin.stop();
    std::sort(lateness.begin(), lateness.end());
    bench.counters["latency_median_ms"] = lateness.empty() ? 0 : lateness[lateness.size() / 2];
    bench.counters["latency_max_ms"] = lateness.empty() ? 0 : lateness.back();
    bench.counters["frames_per_s"] = paints / seconds;
    bench.counters["steps_per_s"] = steps / seconds;
  }
}
BENCHMARK(BM_WorkbenchDuringRun)->Arg(100)->Arg(20)->Iterations(1)->Unit(benchmark::kSecond);

// Instant previews (issue 20): from PreviewController::request to the
// first previewStep on the GUI thread (the first ghost; target < 0.5 s)
// and to previewFinished, on the strip fold and the 20 × 20 diagonal fold.
// Where the first ghost's time goes: building the draft's solver (model
// and checks, measured apart on the same scene) and the first step's own
// time in the solve (StepState::elapsed_s); the rest is the two thread hops.
// The reported time is the first step's (manual time); take the median:
//   xvfb-run -a build/bench/workbench_benchmark --benchmark_filter=Preview
const char* const kPreviewScenes[] = {"strip-fold.json", "diagonal-fold.json"};

void BM_Preview(benchmark::State& bench) {
  App();
  const std::string name = kPreviewScenes[bench.range(0)];
  const Scene scene = ReadScene(std::string(DRAPE_SOURCE_DIR) + "/resources/scenes/" + name);
  bench.SetLabel(name);
  const Scene draft = PreviewController::DraftOf(scene);
  for (auto _ : bench) {
    QElapsedTimer build;
    build.start();
    const ShellSolver solver(draft, SolverOptions::FromScene(draft.solver));
    const double build_ms = build.nsecsElapsed() / 1e6;

    PreviewController previews;
    QEventLoop loop;
    QElapsedTimer clock;
    double first_ms = -1, first_in_solve_ms = 0, finished_ms = 0;
    int steps = 0;
    QObject::connect(
        &previews,
        &PreviewController::previewStep,
        [&](int, std::shared_ptr<const ShellModel>, std::shared_ptr<const StepState> s) {
          if (steps++ == 0) {
            first_ms = clock.nsecsElapsed() / 1e6;
            first_in_solve_ms = 1e3 * s->elapsed_s;
          }
        });
    QObject::connect(&previews, &PreviewController::previewFinished, [&] {
      finished_ms = clock.nsecsElapsed() / 1e6;
      loop.quit();
    });
    QObject::connect(&previews, &PreviewController::previewFailed, [&] { loop.quit(); });
    clock.start();
    previews.request(scene);
    loop.exec();
    bench.SetIterationTime(first_ms / 1e3);
    bench.counters["first_step_ms"] = first_ms;
    bench.counters["finished_ms"] = finished_ms;
    bench.counters["solver_build_ms"] = build_ms;
    bench.counters["first_step_in_solve_ms"] = first_in_solve_ms;
    bench.counters["draft_steps"] = steps;
    bench.counters["draft_nodes"] = solver.model().NodeCount();
  }
}
BENCHMARK(BM_Preview)
    ->DenseRange(0, 1)
    ->Iterations(1)
    ->Repetitions(7)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace drape
