// The workbench's live drag (ui/widgets/live_drag.h), the whole way: the
// gripper handle moved, core's frame computed, the view updated and drawn.
// One benchmark iteration is one frame (40 up, 40 down, 3 cm on the corner
// lift, 2 cm on the diagonal fold, both 20 × 20); `frames_per_second` is
// what a user sees. The issue asks for 10 Hz at 20 × 20, aiming at 30.
// Needs a display:
//   xvfb-run -a build/bench/live_drag_benchmark --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QEventLoop>
#include <QTimer>

#include <string>

#include "ui/render/display.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/handle_controller.h"
#include "ui/widgets/live_drag.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/run_monitor.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

QApplication* App() {
  static int argc = 1;
  static char name[] = "live_drag_benchmark";
  static char* argv[] = {name, nullptr};
  static QApplication* app = [] {
    QSurfaceFormat::setDefaultFormat(VtkViewport::defaultFormat());
    return new QApplication(argc, argv);
  }();
  return app;
}

struct DragCase {
  const char* scene;
  double lift;  // [m]
};
const DragCase kCases[] = {{"tests/data/corner-lift-20x20.json", 0.03},
                           {"resources/scenes/diagonal-fold.json", 0.02}};

void BM_LiveDragFrame(benchmark::State& bench) {
  if (!DisplayProblem().empty()) {
    bench.SkipWithError("no display: run under xvfb-run -a");
    return;
  }
  App();
  const DragCase& c = kCases[bench.range(0)];
  bench.SetLabel(c.scene);
  MainWindow window;
  window.resize(1280, 800);
  window.show();
  window.openScene(QString::fromStdString(std::string(DRAPE_SOURCE_DIR) + "/" + c.scene));
  QEventLoop loop;
  bool done = false;
  QObject::connect(window.runMonitor(), &RunMonitor::finished, &loop, [&] {
    done = true;
    loop.quit();
  });
  QTimer::singleShot(300000, &loop, &QEventLoop::quit);
  window.run();
  loop.exec();
  if (!done) {
    bench.SkipWithError("the scene's run did not finish");
    return;
  }
  // The handles come with the grippers' editor.
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kGrippers, 0));
  QApplication::processEvents();
  LiveDrag* live = window.handles()->liveDrag();
  if (live->handles()->count() == 0) {
    bench.SkipWithError("no gripper handle at the run's end");
    return;
  }
  DragHandles* handles = live->handles();
  const Eigen::Vector3d start = handles->position(0);
  emit handles->started(0);
  const long long paints_before = window.viewport()->paints();
  int frame = 0;
  double worst = 0;
  for (auto _ : bench) {
    const int k = frame++ % 80;
    const double along = k < 40 ? (k + 1) / 40.0 : (79 - k) / 40.0;
    handles->setPosition(0, start + Eigen::Vector3d(0, 0, along * c.lift));
    emit handles->dragged(0);
    // The frame drawn, as the event loop draws it after a mouse move.
    window.viewport()->repaint();
    worst = std::max(worst, live->lastFrame()->residual_ratio);
  }
  bench.counters["frames_per_second"] =
      benchmark::Counter(static_cast<double>(frame), benchmark::Counter::kIsRate);
  bench.counters["paints"] = static_cast<double>(window.viewport()->paints() - paints_before);
  bench.counters["worst_residual_ratio"] = worst;
}
BENCHMARK(BM_LiveDragFrame)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(3.0)
    ->UseRealTime();

}  // namespace
}  // namespace drape
