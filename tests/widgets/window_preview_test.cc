// Instant previews wired through the workbench's window: an accepted edit
// (not an open) starts a draft preview whose steps are drawn as a ghost
// over the last run's end (kept in view, marked stale); the ghost is always
// the newest edit's; Run clears it. Runs under xvfb-run -a.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <cstdio>
#include <memory>
#include <set>

#include "core/fe/shell_model.h"
#include "support/test_paths.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/preview_controller.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/view_controller.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

int DraftNodes(const Scene& scene) {
  return BuildShellModel(PreviewController::DraftOf(scene)).NodeCount();
}

class WindowPreview : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    window_ = std::make_unique<MainWindow>();
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    ASSERT_TRUE(window_->openScene(
        QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
    EXPECT_FALSE(window_->previews()->isBusy())
        << "opening a scene is no edit: " << doc()->undoStack()->count() << " "
        << doc()->undoStack()->text(0).toStdString();
    QSignalSpy finished(window_.get(), &MainWindow::runFinished);
    QElapsedTimer clock;
    clock.start();
    window_->run();
    ASSERT_TRUE(finished.wait(120000));
    std::fprintf(stderr, "the run: %lld ms\n", clock.elapsed());
    ASSERT_FALSE(window_->isRunning());
    ASSERT_GT(window_->stepCount(), 0);
    last_step_ = window_->step(window_->stepCount()).step;
  }
  void TearDown() override { window_.reset(); }

  SceneDocument* doc() const { return window_->document(); }
  FrameRenderer* renderer() const { return window_->view()->renderer(); }
  // An edit as a panel makes it: checked, then applied (one undo step).
  void Edit(const char* what, const Scene& after) {
    QString problem;
    ASSERT_TRUE(doc()->tryApply(what, after, &problem)) << problem.toStdString();
  }
  // The strip fold with another thickness (thinner: a thicker strip would
  // start inside the table, which the solver refuses).
  Scene WithThickness(double h) const {
    Scene s = doc()->scene();
    s.material.thickness = h;
    return s;
  }

  std::unique_ptr<MainWindow> window_;
  int last_step_ = 0;
};

// An edit: within 2 s the edited scene's draft is drawn as a ghost, of the
// newest generation, over the last run's end (kept, said to be stale).
TEST_F(WindowPreview, AnEditShowsItsDraftAsAGhostOverTheLastResult) {
  ASSERT_FALSE(renderer()->HasGhost());
  const double h0 = doc()->scene().material.thickness;
  const Scene edited = WithThickness(0.8 * h0);
  QElapsedTimer clock;
  clock.start();
  Edit("thickness", edited);
  // The last run's end stays in view at step 0, marked stale.
  ASSERT_NE(window_->view()->staleResult(), nullptr);
  EXPECT_EQ(window_->view()->staleResult()->step, last_step_);
  EXPECT_EQ(window_->stepCount(), 0);
  EXPECT_TRUE(window_->view()->stepLabel()->text().contains("stale"))
      << window_->view()->stepLabel()->text().toStdString();
  EXPECT_TRUE(window_->previews()->isBusy());
  ASSERT_TRUE(QTest::qWaitFor([&] { return renderer()->HasGhost(); }, 2000));
  std::fprintf(stderr, "edit to the first ghost in the window: %lld ms\n", clock.elapsed());
  EXPECT_EQ(window_->view()->ghostGeneration(), window_->previews()->generation());
  // The ghost is the draft of the edited scene: half the mesh, its thickness.
  ASSERT_NE(window_->view()->ghostModel(), nullptr);
  EXPECT_DOUBLE_EQ(window_->view()->ghostModel()->thickness, 0.8 * h0);
  EXPECT_EQ(window_->view()->ghostModel()->NodeCount(), DraftNodes(edited));
  EXPECT_LT(window_->view()->ghostModel()->NodeCount(), doc()->model()->NodeCount());
  // A new renderer (another field) draws the ghost too.
  ASSERT_TRUE(window_->setField("curvature"));
  EXPECT_TRUE(renderer()->HasGhost());
  EXPECT_EQ(window_->view()->ghostGeneration(), window_->previews()->generation());
  // The draft completes: the status bar says so.
  ASSERT_TRUE(QTest::qWaitFor([&] { return !window_->previews()->isBusy(); }, 60000));
  EXPECT_EQ(window_->statusBar()->currentMessage().toStdString(),
            "draft preview ready — Run to refine");
  EXPECT_TRUE(renderer()->HasGhost());
}

// Two edits in a burst: the ghost shown is the second's (0.8 h, not 0.9 h),
// never the first's, and so are all the preview's steps drawn.
TEST_F(WindowPreview, TheGhostOfTwoQuickEditsIsTheSecondEdits) {
  const double h0 = doc()->scene().material.thickness;
  std::set<int> generations;
  QObject::connect(window_->previews(), &PreviewController::previewStep, [&](int g, auto, auto) {
    generations.insert(g);
  });
  Edit("thickness", WithThickness(0.9 * h0));
  const int first = window_->previews()->generation();
  Edit("thickness", WithThickness(0.8 * h0));
  const int second = window_->previews()->generation();
  EXPECT_GT(second, first);
  ASSERT_TRUE(QTest::qWaitFor([&] { return renderer()->HasGhost(); }, 2000));
  EXPECT_EQ(window_->view()->ghostGeneration(), second);
  EXPECT_DOUBLE_EQ(window_->view()->ghostModel()->thickness, 0.8 * h0);
  ASSERT_TRUE(QTest::qWaitFor([&] { return !window_->previews()->isBusy(); }, 60000));
  QTest::qWait(100);
  EXPECT_EQ(generations, std::set<int>{second});
  EXPECT_DOUBLE_EQ(window_->view()->ghostModel()->thickness, 0.8 * h0);

  // An edit after a ghost is up: the old ghost goes with the edit, the new
  // one is the remeshed scene's (other nodes; the stale result cannot stay).
  Scene remeshed = doc()->scene();
  remeshed.fabric.mesh.elements = std::array<int, 2>{60, 2};
  Edit("mesh", remeshed);
  EXPECT_FALSE(renderer()->HasGhost());
  EXPECT_EQ(window_->view()->staleResult(), nullptr);
  ASSERT_TRUE(QTest::qWaitFor([&] { return renderer()->HasGhost(); }, 2000));
  EXPECT_EQ(window_->view()->ghostModel()->NodeCount(), DraftNodes(remeshed));
  EXPECT_EQ(window_->view()->ghostGeneration(), window_->previews()->generation());
  // Undo is an edit as well: it previews the scene it goes back to.
  doc()->undoStack()->undo();
  ASSERT_TRUE(QTest::qWaitFor([&] { return renderer()->HasGhost(); }, 2000));
  EXPECT_DOUBLE_EQ(window_->view()->ghostModel()->thickness, 0.8 * h0);
}

// Run cancels the preview and clears the ghost; the run's steps replace
// the stale result. Opening a scene previews nothing; a preview that fails
// says why in the status bar.
TEST_F(WindowPreview, RunClearsTheGhostAndOpeningPreviewsNothing) {
  Edit("thickness", WithThickness(0.8 * doc()->scene().material.thickness));
  ASSERT_TRUE(QTest::qWaitFor([&] { return renderer()->HasGhost(); }, 2000));
  QSignalSpy finished(window_.get(), &MainWindow::runFinished);
  window_->run();
  EXPECT_FALSE(renderer()->HasGhost());
  EXPECT_FALSE(window_->previews()->isBusy());
  EXPECT_EQ(window_->view()->staleResult(), nullptr);
  ASSERT_TRUE(finished.wait(120000));
  QTest::qWait(100);
  EXPECT_FALSE(renderer()->HasGhost()) << "no preview step came after the run began";
  EXPECT_GT(window_->stepCount(), 0);

  const int generation = window_->previews()->generation();
  ASSERT_TRUE(
      window_->openScene(QString::fromStdString((test::ScenesDir() / "strip-fold.json").string())));
  EXPECT_FALSE(window_->previews()->isBusy());
  EXPECT_EQ(window_->view()->staleResult(), nullptr);
  EXPECT_EQ(window_->view()->stepLabel()->text().toStdString(), "reference state");
  QTest::qWait(300);
  EXPECT_FALSE(renderer()->HasGhost());
  EXPECT_LE(window_->previews()->generation(), generation + 1);  // at most a cancel

  // An edit the solver refuses (twice as thick, the strip starts inside the
  // table): no ghost, and the status bar says why.
  Edit("thickness", WithThickness(2 * doc()->scene().material.thickness));
  ASSERT_TRUE(QTest::qWaitFor([&] { return !window_->previews()->isBusy(); }, 10000));
  const std::string said = window_->statusBar()->currentMessage().toStdString();
  EXPECT_EQ(said.rfind("no draft preview: obstacles: the fabric starts inside an obstacle", 0), 0)
      << said;
  EXPECT_FALSE(renderer()->HasGhost());
}

}  // namespace
}  // namespace drape
