// The workbench's parts, each on its own: the document's one model per
// accepted edit (shared by the view and the panels), picking, the drag
// handles, the view's timeline, the document's acceptance of changes.
#include <gtest/gtest.h>

#include <memory>
#include <variant>

#include <QLabel>
#include <QListWidget>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QUndoStack>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "support/test_paths.h"
#include "ui/widgets/document_controller.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/editor_docks.h"
#include "ui/widgets/handle_controller.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/path_handles.h"
#include "ui/widgets/picking_controller.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/run_monitor.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/stages_panel.h"
#include "ui/widgets/view_controller.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

QString StripFold() {
  return QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
}

class WorkbenchParts : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    window_ = std::make_unique<MainWindow>();
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    ASSERT_TRUE(window_->openScene(StripFold()));
  }
  void TearDown() override { window_.reset(); }

  std::unique_ptr<MainWindow> window_;
};

TEST_F(WorkbenchParts, AnAcceptedEditBuildsOneModelThatTheViewAndThePanelsShare) {
  SceneDocument* doc = window_->document();
  auto shared = [&] {
    ASSERT_NE(doc->model(), nullptr);
    EXPECT_EQ(window_->view()->model(), doc->model());
    EXPECT_EQ(window_->properties()->model(), doc->model());
  };
  shared();
  const long long before = SceneDocument::modelBuilds();
  Scene thicker = doc->scene();
  thicker.material.thickness *= 2;
  QString problem;
  ASSERT_TRUE(doc->tryApply("thickness", thicker, &problem)) << problem.toStdString();
  EXPECT_EQ(SceneDocument::modelBuilds(), before + 1) << "check() and the window each built one";
  shared();
  EXPECT_DOUBLE_EQ(doc->model()->thickness, thicker.material.thickness);
  // Undo and redo are changes of the scene too: one model each.
  doc->undoStack()->undo();
  EXPECT_EQ(SceneDocument::modelBuilds(), before + 2);
  shared();
  doc->undoStack()->redo();
  EXPECT_EQ(SceneDocument::modelBuilds(), before + 3);
  shared();
  // Opening is one as well (it was three: the window's check, the
  // window's model and nothing shared with the panel, which meshed).
  const long long at_open = SceneDocument::modelBuilds();
  ASSERT_TRUE(window_->openScene(StripFold()));
  EXPECT_EQ(SceneDocument::modelBuilds(), at_open + 1);
  shared();
  EXPECT_EQ(window_->properties()->meshInfo()->text().toStdString(),
            "243 nodes, 160 elements, 1215 DOFs");
}

// The docks: what the tree chooses comes up with its item selected (the
// editors tabbed behind it hidden), the stages' tab coming up says so (its
// path handles follow), and a run's lock disables every editor.
TEST_F(WorkbenchParts, TheDocksRaiseWhatTheTreeChoosesAndLockTheEditors) {
  EditorDocks* docks = window_->docks();
  QSignalSpy stages_shown(docks, &EditorDocks::stagesShown);
  emit window_->tree()->chosen(ModelTree::Part::kGrippers, 0, -1);
  QTest::qWait(50);
  // A dock tabbed behind another still says isVisible(); what shows has a
  // visible region.
  auto shown = [](QWidget* w) { return !w->visibleRegion().isEmpty(); };
  EXPECT_TRUE(shown(docks->grippers()));
  EXPECT_FALSE(shown(docks->supports()));
  EXPECT_EQ(docks->grippers()->list()->currentRow(), 0);
  emit window_->tree()->chosen(ModelTree::Part::kStages, 1, -1);
  QTest::qWait(50);
  EXPECT_TRUE(shown(docks->stages()));
  EXPECT_FALSE(shown(docks->grippers()));
  EXPECT_EQ(docks->stages()->list()->currentRow(), 1);
  ASSERT_FALSE(stages_shown.isEmpty());
  EXPECT_TRUE(stages_shown.last().at(0).toBool());

  docks->setEditable(false);
  for (QWidget* editor : std::initializer_list<QWidget*>{docks->properties(),
                                                         docks->stages(),
                                                         docks->supports(),
                                                         docks->grippers(),
                                                         docks->obstacles(),
                                                         docks->loads(),
                                                         docks->probes()})
    EXPECT_FALSE(editor->isEnabled()) << editor->metaObject()->className();
  docks->setEditable(true);
  EXPECT_TRUE(docks->probes()->isEnabled());
}

TEST_F(WorkbenchParts, PickingANodeTwiceTogglesItAndTheEditorsHear) {
  PickingController* picking = window_->picking();
  const ShellModel& model = *window_->document()->model();
  QSignalSpy published(picking, &PickingController::pickedChanged);
  const Eigen::Vector3d near_7 =
      model.reference.positions.row(7).transpose() + Eigen::Vector3d(1e-5, 0, 0);
  picking->pickNear(near_7);
  ASSERT_EQ(picking->picked(), std::vector<int>{7});
  EXPECT_EQ(window_->pickedNodes(), std::vector<int>{7});
  ASSERT_EQ(published.count(), 1);
  const auto at = published.last().at(1).value<std::vector<std::array<double, 2>>>();
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0][0], model.reference.positions(7, 0));
  EXPECT_EQ(at[0][1], model.reference.positions(7, 1));
  picking->pickNear(model.reference.positions.row(12).transpose());
  EXPECT_EQ(picking->picked(), (std::vector<int>{7, 12}));
  picking->pickNear(near_7);
  EXPECT_EQ(picking->picked(), std::vector<int>{12});
  picking->clear();
  EXPECT_TRUE(picking->picked().empty());
}

TEST_F(WorkbenchParts, AHandleLetGoIsOneUndoableEditAndARefusedOneGoesBack) {
  SceneDocument* doc = window_->document();
  HandleController* handles = window_->handles();
  const Scene original = doc->scene();
  // The fold stage R's arc, chosen in the scene tree: the stages' editor
  // comes up and selects it (and again after each edit).
  window_->tree()->setCurrentItem(window_->tree()->item(ModelTree::Part::kStages, 1, 0));
  ASSERT_EQ(window_->pathHandles()->count(), 3);
  // No handles while a run works on the scene.
  handles->setEditable(false);
  EXPECT_EQ(window_->pathHandles()->count(), 0);
  handles->setEditable(true);
  ASSERT_EQ(window_->pathHandles()->count(), 3);

  ArcPath quarter = std::get<ArcPath>(original.stages[1].moves[0].path);
  quarter.angle_deg = 90;
  const int edits = doc->undoStack()->count();
  const long long builds = SceneDocument::modelBuilds();
  emit window_->pathHandles()->released(quarter);
  QTest::qWait(20);  // applied once VTK is done with the drag's events
  EXPECT_EQ(doc->undoStack()->count(), edits + 1);
  EXPECT_EQ(SceneDocument::modelBuilds(), builds + 1);
  EXPECT_EQ(std::get<ArcPath>(doc->scene().stages[1].moves[0].path).angle_deg, 90);
  EXPECT_EQ(window_->pathHandles()->count(), 3) << "the handles are back on the new renderer";
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene(), original);

  // A path the reader refuses changes nothing and says why.
  ArcPath flat = quarter;
  flat.axis = {0, 0, 0};
  QSignalSpy said(handles, &HandleController::message);
  emit window_->pathHandles()->released(flat);
  QTest::qWait(20);
  EXPECT_EQ(doc->scene(), original);
  ASSERT_EQ(said.count(), 1);
  EXPECT_FALSE(said.last().at(0).toString().isEmpty());
  EXPECT_EQ(window_->pathHandles()->count(), 3);
}

TEST_F(WorkbenchParts, TheTimelineShowsStepI) {
  ViewController* view = window_->view();
  const ShellModel& model = *view->model();
  for (int i = 1; i <= 3; ++i) {
    auto step = std::make_shared<StepState>();
    step->step = i;
    step->stage_name = "R";
    step->lambda = i / 4.0;
    step->negative_pivots = i == 2 ? 1 : 0;  // step 2 one a part could not rest in
    step->state = model.reference;
    step->state.positions.col(2).array() += 0.01 * i;
    step->state.obstacles.assign(view->scene().obstacles.size(), ObstaclePlacement{});
    view->addStep(step);
  }
  EXPECT_EQ(view->stepCount(), 3);
  EXPECT_EQ(view->timeline()->maximum(), 3);
  QTest::qWait(20);  // the view follows the newest step, once
  EXPECT_EQ(view->currentStep(), 3);
  EXPECT_EQ(view->stepLabel()->text().toStdString(),
            "step 3 of 3, stable rest state: yes — R 75 %");

  QSignalSpy shown(view, &ViewController::stepShown);
  view->timeline()->setValue(2);
  ASSERT_EQ(shown.count(), 1);
  EXPECT_EQ(shown.last().at(0).toInt(), 2);
  EXPECT_EQ(window_->currentStep(), 2);
  EXPECT_EQ(view->stepLabel()->text().toStdString(), "step 2 of 3, stable rest state: no — R 50 %");
  EXPECT_EQ(view->shownPositions(), view->step(2).state.positions);
  window_->showStep(0);
  EXPECT_EQ(view->stepLabel()->text().toStdString(), "reference state");
  EXPECT_EQ(view->shownPositions(), model.reference.positions);

  // A new look remakes the renderer; a name it does not know changes nothing.
  QSignalSpy remade(view, &ViewController::rendererChanged);
  EXPECT_FALSE(view->setField("no such field"));
  EXPECT_FALSE(view->setCamera("below"));
  EXPECT_EQ(remade.count(), 0);
  EXPECT_TRUE(view->setCamera("top"));
  EXPECT_EQ(remade.count(), 1);
}

TEST_F(WorkbenchParts, AChangeTheEngineCannotModelIsTakenBackWithItsMessage) {
  SceneDocument* doc = window_->document();
  const Scene original = doc->scene();
  const auto model = doc->model();
  QSignalSpy accepted(window_->documentController(), &DocumentController::accepted);
  QSignalSpy said(window_->documentController(), &DocumentController::message);
  Scene held_nowhere = original;
  held_nowhere.supports[0].select.shape = NodesSelection{{100000}};
  doc->apply("hold node 100000", held_nowhere);  // unchecked: the document models it
  EXPECT_EQ(doc->model(), nullptr);
  EXPECT_FALSE(doc->modelProblem().isEmpty());
  ASSERT_GE(said.count(), 1);
  EXPECT_EQ(said.first().at(0).toString(), doc->modelProblem());
  EXPECT_EQ(window_->view()->model(), model) << "the view keeps the scene it showed";
  QTest::qWait(20);
  std::cerr << "undo index " << doc->undoStack()->index() << " count " << doc->undoStack()->count()
            << " " << doc->modelProblem().toStdString() << "\n";
  EXPECT_EQ(doc->scene(), original);
  ASSERT_NE(doc->model(), nullptr);
  ASSERT_EQ(accepted.count(), 1);  // the undo
  EXPECT_FALSE(accepted.last().at(0).toBool()) << "the same nodes as before";

  // Another mesh: picks on the old one go.
  window_->picking()->pickNear(doc->model()->reference.positions.row(3).transpose());
  ASSERT_EQ(window_->pickedNodes().size(), 1u);
  Scene finer = doc->scene();
  finer.fabric.mesh.elements = std::array<int, 2>{40, 2};
  QString problem;
  ASSERT_TRUE(doc->tryApply("mesh 40 x 2", finer, &problem)) << problem.toStdString();
  EXPECT_TRUE(accepted.last().at(0).toBool());
  EXPECT_TRUE(window_->pickedNodes().empty());
  EXPECT_EQ(window_->view()->model()->NodeCount(), 123);
}

TEST_F(WorkbenchParts, ARunFeedsTheViewAndPlotsAndHoldsEditsUntilItEnds) {
  window_->tree()->setCurrentItem(window_->tree()->item(ModelTree::Part::kStages, 1, 0));
  ASSERT_EQ(window_->pathHandles()->count(), 3);
  RunMonitor* monitor = window_->runMonitor();
  QSignalSpy finished(monitor, &RunMonitor::finished);
  window_->run();
  EXPECT_TRUE(monitor->isRunning());
  EXPECT_TRUE(window_->document()->isLocked());
  EXPECT_EQ(window_->pathHandles()->count(), 0) << "no drags while the run works on the scene";
  ASSERT_TRUE(finished.wait(120000));
  EXPECT_FALSE(monitor->isRunning());
  EXPECT_FALSE(window_->document()->isLocked());
  EXPECT_EQ(window_->pathHandles()->count(), 3);
  ASSERT_GT(window_->stepCount(), 0);
  EXPECT_EQ(window_->step(window_->stepCount()).step, window_->stepCount());
  QTest::qWait(20);
  EXPECT_EQ(window_->currentStep(), window_->stepCount()) << "the view followed the run";
}

}  // namespace
}  // namespace drape
