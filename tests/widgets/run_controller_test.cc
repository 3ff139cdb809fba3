// A workbench run without the window (ui/widgets/run_controller): every
// step arrives in order before `finished`, one run at a time, Stop keeps the
// steps so far, and a scene the engine refuses says why, then finishes.
#include "ui/widgets/run_controller.h"

#include <QSignalSpy>
#include <QTest>

#include "core/io/scene_reader.h"
#include "gui_test.h"
#include "support/test_paths.h"

namespace drape {
namespace {

TEST_F(Widgets, ARunDeliversEveryStepInOrderThenFinishes) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  RunController runs;
  std::vector<int> steps;
  bool finished_after_steps = false;
  QObject::connect(&runs, &RunController::stepConverged, [&](std::shared_ptr<const StepState> s) {
    steps.push_back(s->step);
  });
  QSignalSpy finished(&runs, &RunController::finished);
  QObject::connect(&runs, &RunController::finished, [&](const SolveSummary& summary) {
    finished_after_steps = static_cast<int>(steps.size()) == summary.steps && !runs.isRunning();
  });
  ASSERT_TRUE(runs.start(scene));
  EXPECT_TRUE(runs.isRunning());
  EXPECT_FALSE(runs.start(scene));  // one run at a time
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_TRUE(finished_after_steps);
  for (size_t i = 0; i < steps.size(); ++i) EXPECT_EQ(steps[i], static_cast<int>(i) + 1);
  EXPECT_FALSE(runs.isRunning());
  EXPECT_TRUE(runs.start(scene));  // and again once it is done
  ASSERT_TRUE(finished.wait(60000));
}

TEST_F(Widgets, StopKeepsTheStepsSoFar) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-fold.json");
  RunController runs;
  int steps = 0;
  QObject::connect(&runs, &RunController::stepConverged, [&](std::shared_ptr<const StepState>) {
    if (++steps == 3) runs.stop();
  });
  QSignalSpy finished(&runs, &RunController::finished);
  ASSERT_TRUE(runs.start(scene));
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  EXPECT_EQ(summary.termination, Termination::kCancelled) << summary.message;
  EXPECT_GE(steps, 3);
  EXPECT_EQ(summary.steps, steps);  // every step the solver made was delivered
  EXPECT_LT(steps, 66);             // the fold has 66
}

TEST_F(Widgets, ASceneTheEngineRefusesSaysWhyThenFinishes) {
  Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  scene.supports.clear();
  scene.grippers.clear();
  scene.obstacles.clear();  // nothing holds the fabric
  scene.stages.resize(1);
  RunController runs;
  QSignalSpy failed(&runs, &RunController::failed);
  QSignalSpy finished(&runs, &RunController::finished);
  ASSERT_TRUE(runs.start(scene));
  ASSERT_TRUE(finished.wait(60000));
  ASSERT_EQ(failed.count(), 1);
  EXPECT_NE(failed.at(0).at(0).toString().toStdString().find("nothing holds the fabric"),
            std::string::npos)
      << failed.at(0).at(0).toString().toStdString();
  EXPECT_EQ(finished.at(0).at(0).value<SolveSummary>().termination, Termination::kInvalidInput);
  EXPECT_FALSE(runs.isRunning());
}

}  // namespace
}  // namespace drape
