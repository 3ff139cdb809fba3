// The run dock's reaction plot: what each support and gripper carries along
// the shipped strip fold, plotted live as the workbench runs it, equals
// result.json's steps[].reactions of the same scene solved by core and
// written by ResultWriter; the marker follows the timeline; a released
// gripper's line ends at its release.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include <QComboBox>
#include <QDockWidget>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "core/io/result_writer.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/unit_settings.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

// |a − b| ≤ 1e-9 max(|a|, |b|): equal to round-off (and both 0 when one is).
::testing::AssertionResult Relative(double plotted, double expected) {
  if (std::abs(plotted - expected) <= 1e-9 * std::max(std::abs(plotted), std::abs(expected)))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "plotted " << plotted << ", result.json " << expected;
}

// The strip fold as `drape run` writes it: core's solver, every step to
// ResultWriter, result.json read back.
nlohmann::json SolveAndWrite(const Scene& scene, const std::filesystem::path& directory) {
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ResultWriter writer(directory, scene, solver.model());
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    writer.AddStep(s);
    return StepDecision::kContinue;
  }});
  writer.Finish(summary);
  std::ifstream in(directory / kResultFileName);
  return nlohmann::json::parse(in);
}

TEST_F(Widgets, ReactionPlotShowsEachHoldsForceLiveAsResultJsonHasIt) {
  const auto file = test::ScenesDir() / "strip-fold.json";
  QTemporaryDir folder;
  ASSERT_TRUE(folder.isValid());
  const nlohmann::json result =
      SolveAndWrite(ReadScene(file), std::filesystem::path(folder.path().toStdString()) / "run");
  const nlohmann::json& steps = result.at("steps");
  ASSERT_GT(steps.size(), 10u);

  MainWindow window;
  window.units()->useChoice(UnitSystem::kSI);  // the plot in N, as result.json (not the scene's gf)
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(QString::fromStdString(file.string())));
  ReactionPlot* plot = window.reactionPlot();
  ASSERT_NE(plot, nullptr);
  EXPECT_EQ(plot->markerStep(), -1);  // nothing plotted, no marker
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  // Live: with the run paused after its first steps, the plot has a point
  // per hold for every step come so far, and the run is not over.
  ASSERT_TRUE(QTest::qWaitFor([&] { return window.stepCount() >= 1; }, 30000));
  window.pauseOrResume();
  QTest::qWait(300);  // the steps already queued arrive
  ASSERT_EQ(finished.count(), 0);
  EXPECT_TRUE(window.isRunning());
  const int live = window.stepCount();
  EXPECT_GT(live, 0);
  EXPECT_LT(live, static_cast<int>(steps.size()));
  ASSERT_EQ(plot->holds(), 2);  // far_end (the support), end (the gripper)
  for (int h = 0; h < plot->holds(); ++h) EXPECT_EQ(plot->points(h), live);
  window.pauseOrResume();
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  ASSERT_EQ(window.stepCount(), static_cast<int>(steps.size()));

  // Every step of every hold: the norm of result.json's reaction.
  EXPECT_EQ(plot->holdName(0).toStdString(), "far_end");
  EXPECT_EQ(plot->holdName(1).toStdString(), "end");
  EXPECT_EQ(plot->mode(), ReactionPlot::Mode::kMagnitude);
  double largest = 0;
  for (int h = 0; h < plot->holds(); ++h) {
    const std::string name = plot->holdName(h).toStdString();
    ASSERT_EQ(plot->points(h), static_cast<int>(steps.size())) << name;
    for (int k = 0; k < plot->points(h); ++k) {
      const nlohmann::json& step = steps[static_cast<size_t>(k)];
      EXPECT_EQ(plot->step(h, k), step.at("step").get<int>());
      const auto r = step.at("reactions").at(name).get<std::vector<double>>();
      ASSERT_EQ(r.size(), 3u);
      const double norm = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
      EXPECT_TRUE(std::isfinite(plot->value(h, k))) << name << " step " << k + 1;
      EXPECT_TRUE(plot->force(h, k).allFinite()) << name << " step " << k + 1;
      EXPECT_TRUE(Relative(plot->value(h, k), norm)) << name << " step " << k + 1;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(Relative(plot->force(h, k)[c], r[c]));
      largest = std::max(largest, norm);
    }
  }
  // Early in the arc the gripper pulls the strip against the pinned far
  // end: about 16 mN, more than twice the strip's weight (6.9 mN).
  EXPECT_GT(largest, 0.01);

  // A component: the plotted values become F_z, the combo box says so.
  plot->setMode(ReactionPlot::Mode::kZ);
  EXPECT_EQ(plot->modeBox()->currentIndex(), 3);
  for (int h = 0; h < plot->holds(); ++h) {
    const std::string name = plot->holdName(h).toStdString();
    for (int k = 0; k < plot->points(h); ++k)
      EXPECT_TRUE(Relative(plot->value(h, k),
                           steps[static_cast<size_t>(k)].at("reactions").at(name)[2].get<double>()))
          << name << " step " << k + 1;
  }
  plot->modeBox()->setCurrentIndex(0);  // as the user picks it
  EXPECT_EQ(plot->mode(), ReactionPlot::Mode::kMagnitude);

  // The marker follows the timeline: at the last step while following the
  // run, then wherever the timeline goes.
  QTest::qWait(50);
  EXPECT_EQ(plot->markerStep(), window.stepCount());
  window.showStep(10);
  EXPECT_EQ(plot->markerStep(), 10);
  window.showStep(0);
  EXPECT_EQ(plot->markerStep(), 0);

  if (const char* shot = std::getenv("DRAPE_REACTION_SHOT")) {  // to look at it
    window.showStep(window.stepCount() / 2);
    qobject_cast<QDockWidget*>(plot->parentWidget())->raise();
    QTest::qWait(200);
    EXPECT_TRUE(window.grab().save(shot));
  }

  // A new run starts a clean plot.
  window.run();
  EXPECT_EQ(plot->holds(), 0);
  window.stop();
  ASSERT_TRUE(finished.wait(30000));
}

// A gripper released in stage 1 gets no points from that stage on; the
// support goes on. (Reactions as the solver reports them: a released
// gripper's is zero.)
TEST_F(Widgets, ReactionPlotEndsAReleasedGrippersLine) {
  Scene scene;
  scene.stages.resize(2);
  scene.stages[1].release = {"end"};
  ReactionPlot plot;
  plot.setScene(scene);
  for (int k = 1; k <= 6; ++k) {
    StepState s;
    s.stage = k <= 3 ? 0 : 1;
    s.step = k;
    s.reactions = {{"pin", Eigen::Vector3d(0, 0, 0.1 * k)},
                   {"end", k <= 3 ? Eigen::Vector3d(3, 4, 0) : Eigen::Vector3d::Zero()}};
    plot.add(s);
  }
  ASSERT_EQ(plot.holds(), 2);
  EXPECT_EQ(plot.points(0), 6);
  EXPECT_EQ(plot.points(1), 3);
  EXPECT_DOUBLE_EQ(plot.value(1, 2), 5);
  EXPECT_EQ(plot.step(1, 2), 3);
  EXPECT_DOUBLE_EQ(plot.value(0, 5), 0.6);
  plot.setCurrentStep(4);
  EXPECT_EQ(plot.markerStep(), 4);
  plot.setMode(ReactionPlot::Mode::kX);
  EXPECT_DOUBLE_EQ(plot.value(1, 0), 3);
  EXPECT_DOUBLE_EQ(plot.value(0, 0), 0);
  plot.clear();
  EXPECT_EQ(plot.holds(), 0);
  EXPECT_EQ(plot.markerStep(), -1);
}

}  // namespace
}  // namespace drape
