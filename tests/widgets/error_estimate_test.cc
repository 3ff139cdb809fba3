// The workbench's error estimate (solver.error_estimate): after a complete
// run the worker solves the scene on meshes 2 and 4 times coarser with
// core's EstimateError, and the window shows Describe()'s line beside the
// run's summary, the per-probe errors in its tooltip. The scene is Peirce's
// heavy strip (α = 8) on 16 elements, as tests/cli/error_estimate_cli_test.cc.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QThread>

#include "core/io/scene_writer.h"
#include "core/solve/error_estimate.h"
#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/run_controller.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/solver_worker.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

Scene HeavyStrip() {
  test::StripSpec spec;
  spec.elements = 16;
  return test::HeavyStrip(spec, 8);
}

// The estimate computed here, apart from the GUI: the scene solved by the
// engine, its final step's probes, EstimateError on them.
ErrorEstimate IndependentEstimate(const Scene& scene) {
  const SolverOptions options = SolverOptions::FromScene(scene.solver);
  std::vector<NamedVector> last;
  const SolveSummary summary = ShellSolver(scene, options).Solve({[&](const StepState& s) {
    last = s.probes;
    return StepDecision::kContinue;
  }});
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  return EstimateError(scene, options, last);
}

void ExpectFinite(const ErrorEstimate& e) {
  EXPECT_TRUE(std::isfinite(e.order));
  for (const ProbeErrorEstimate& p : e.probes) {
    EXPECT_TRUE(std::isfinite(p.error)) << p.name;
    EXPECT_TRUE(std::isfinite(p.gci)) << p.name;
    EXPECT_TRUE(p.extrapolated.allFinite()) << p.name;
  }
}

class ErrorEstimateWidgets : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    dir_ = fs::temp_directory_path() / ("drape-studio-estimate-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The worker's signals in order: the run's steps, the estimate begun, the
// estimate, the end; Stop while it estimates ends it without an estimate.
TEST_F(ErrorEstimateWidgets, WorkerEstimatesAfterTheRunAndStopEndsTheEstimate) {
  Scene scene = HeavyStrip();
  scene.solver.error_estimate = true;
  for (const bool stop : {false, true}) {
    SCOPED_TRACE(stop ? "stopped while estimating" : "estimated");
    SolverWorker worker;
    QThread thread;
    worker.moveToThread(&thread);
    thread.start();
    std::mutex mutex;
    std::vector<std::string> events;
    auto record = [&](const std::string& e) {
      std::lock_guard lock(mutex);
      if (events.empty() || events.back() != e) events.push_back(e);
    };
    std::atomic<bool> finished{false};
    QObject::connect(
        &worker,
        &SolverWorker::stepConverged,
        &worker,
        [&](std::shared_ptr<const StepState>) {
          record("step");
          worker.consumed();
        },
        Qt::DirectConnection);
    QObject::connect(
        &worker,
        &SolverWorker::estimatingError,
        &worker,
        [&] {
          record("estimating");
          if (stop) worker.stop();
        },
        Qt::DirectConnection);
    QObject::connect(
        &worker,
        &SolverWorker::errorEstimated,
        &worker,
        [&](const ErrorEstimate&) { record("estimate"); },
        Qt::DirectConnection);
    QObject::connect(
        &worker,
        &SolverWorker::finished,
        &worker,
        [&](const SolveSummary& s) {
          record(s.IsComplete() ? "finished" : "incomplete");
          finished = true;
        },
        Qt::DirectConnection);
    QMetaObject::invokeMethod(
        &worker, [&] { worker.run(scene); }, Qt::QueuedConnection);
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.load(); }, 60000));
    thread.quit();
    thread.wait();
    const std::vector<std::string> expected =
        stop ? std::vector<std::string>{"step", "estimating", "finished"}
             : std::vector<std::string>{"step", "estimating", "estimate", "finished"};
    EXPECT_EQ(events, expected);
  }
}

// With solver.error_estimate the status bar has the run's summary and,
// beside it, core's Describe() of the same estimate computed here (the
// same numbers); the tooltip has each probe's error. Without it, none.
TEST_F(ErrorEstimateWidgets, WorkbenchShowsTheRunsErrorEstimateBesideItsSummary) {
  const Scene strip = HeavyStrip();
  WriteScene(strip, dir_ / "strip.json");
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(QString::fromStdString((dir_ / "strip.json").string())));
  // The property panel's checkbox is not there yet: the loaded scene's
  // flag set through the document, as the checkbox will.
  Scene on = window.document()->scene();
  ASSERT_FALSE(on.solver.error_estimate);
  on.solver.error_estimate = true;
  window.document()->apply("error estimate on", on);
  ASSERT_TRUE(window.document()->scene().solver.error_estimate);

  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(window.statusBar()->currentMessage().toStdString(), summary.BriefReport());

  const ErrorEstimate expected = IndependentEstimate(window.document()->scene());
  ASSERT_TRUE(expected.in_asymptotic_range) << expected.reason;
  ExpectFinite(expected);
  ASSERT_TRUE(window.errorEstimate().has_value());
  const ErrorEstimate& shown = *window.errorEstimate();
  ExpectFinite(shown);
  EXPECT_TRUE(shown.in_asymptotic_range) << shown.reason;
  EXPECT_EQ(shown.meshes, expected.meshes);
  EXPECT_NEAR(shown.order, expected.order, 1e-9);
  ASSERT_EQ(shown.probes.size(), expected.probes.size());
  for (size_t i = 0; i < shown.probes.size(); ++i) {
    EXPECT_EQ(shown.probes[i].name, expected.probes[i].name);
    EXPECT_NEAR(shown.probes[i].error, expected.probes[i].error, 1e-9 * expected.probes[i].error);
  }
  const QLabel* label = window.errorEstimateLabel();
  ASSERT_NE(label, nullptr);
  EXPECT_TRUE(label->isVisible());
  std::printf("status bar: %s | %s\n",
              qPrintable(window.statusBar()->currentMessage()),
              qPrintable(label->text()));
  EXPECT_EQ(label->text().toStdString(), Describe(expected));
  EXPECT_NE(label->text().toStdString().find("error estimate (16 x 1, 8 x 1, 4 x 1): order 2."),
            std::string::npos);
  const std::string tooltip = label->toolTip().toStdString();
  std::printf("tooltip:\n%s\n", tooltip.c_str());
  EXPECT_NE(tooltip.find("tip: error "), std::string::npos) << tooltip;
  EXPECT_NE(tooltip.find("root: error 0 mm"), std::string::npos) << tooltip;

  // Off again: the next run shows no estimate.
  Scene off = window.document()->scene();
  off.solver.error_estimate = false;
  window.document()->apply("error estimate off", off);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  EXPECT_TRUE(finished.takeFirst().at(0).value<SolveSummary>().IsComplete());
  EXPECT_FALSE(window.errorEstimate().has_value());
  EXPECT_FALSE(label->isVisible());
  EXPECT_TRUE(label->text().isEmpty());
}

// Four pinned corners converge slower than the elements' order: the label
// gives the reason and no error, as `drape run` does.
TEST_F(ErrorEstimateWidgets, OutsideTheAsymptoticRangeTheReasonIsShownNotANumber) {
  ErrorEstimate none;
  none.meshes = {"16 x 16", "8 x 8", "4 x 4"};
  none.reason = "probe 'centre' converges at an observed order of 0.52";
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  // As the worker's queued signal would deliver it.
  emit window.runMonitor()->controller()->estimated(none);
  const QLabel* label = window.errorEstimateLabel();
  EXPECT_TRUE(label->isVisible());
  EXPECT_EQ(label->text().toStdString(), Describe(none));
  EXPECT_NE(label->text().toStdString().find(": none, probe 'centre'"), std::string::npos);
  EXPECT_EQ(label->toolTip().toStdString(), Describe(none));
  EXPECT_EQ(label->toolTip().indexOf(" mm"), -1);
}

}  // namespace
}  // namespace drape
