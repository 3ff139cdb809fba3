// The workbench's editors of what moves the fabric, driven as a user would:
// a path handle dragged with the mouse in the viewport, nodes picked by
// clicking the fabric, moves and stages typed in. Each edit is checked
// against geometry computed here, undone, redone, and survives save and
// reopen. The scene's parts: part_editors_test.cc; the tree, the camera,
// the solver and the guards: workbench_editors_test.cc.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabBar>
#include <QTest>
#include <QUndoStack>

#include "core/fe/path_handles.h"
#include "core/fe/prescribed_motion.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/model/obstacle_anchor.h"
#include "support/editor_input.h"
#include "support/test_paths.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/path_handles.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/selection_rule.h"
#include "ui/widgets/stages_panel.h"
#include "ui/widgets/typed_json.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

using test::Drag;
using test::OnScreen;
using test::StripFold;
using test::TempFile;

TEST_F(Widgets, DraggingAPathHandleEditsThePathUndoablyAndItIsSaved) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  const Scene original = doc->scene();
  // The fold stage R's move, chosen in the scene tree: the stages editor
  // comes up and the arc gets its handles.
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kStages, 1, 0));
  ASSERT_EQ(window.stages()->list()->currentRow(), 1);
  PathHandles* handles = window.pathHandles();
  ASSERT_EQ(handles->count(), 3);           // centre, end, axis
  const Eigen::Vector3d start(-0.1, 0, 0);  // the left edge's centroid
  const Eigen::Vector3d c = handles->position(0);
  EXPECT_LT((c - Eigen::Vector3d(0, 0, 0.75 * 0.0469e-2)).norm(), 1e-12);
  EXPECT_LT(
      (handles->position(1) - MotionAt(original.stages[1].moves[0].path, 1).Apply(start)).norm(),
      1e-12);
  QTest::qWait(200);  // drawn, so the camera maps world to screen

  QSignalSpy previews(handles, &PathHandles::previewed);
  const QPoint from = OnScreen(window.viewport(), handles->position(1));
  const QPoint to = from + QPoint(-40, -90);
  Drag(window.viewport(), from, to);
  EXPECT_GE(previews.count(), 5);  // the path followed the hand
  const Eigen::Vector3d dropped = handles->position(1);
  EXPECT_GT((dropped - MotionAt(original.stages[1].moves[0].path, 1).Apply(start)).norm(), 0.005)
      << "the drag did not move the handle";
  QTest::qWait(50);  // the edit is applied after VTK's events

  // The held edge now ends in the dropped direction, seen along the axis.
  const auto& arc = std::get<ArcPath>(doc->scene().stages[1].moves[0].path);
  EXPECT_NE(arc.angle_deg, 180.0);
  EXPECT_EQ(arc.axis, (Vec3{0, 1, 0}));
  const Eigen::Vector3d end = MotionAt(arc, 1).Apply(start);
  auto in_plane = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v.x() - c.x(), 0, v.z() - c.z());
  };
  EXPECT_LT(in_plane(end).normalized().cross(in_plane(dropped).normalized()).norm(), 1e-9);
  EXPECT_GT(in_plane(end).dot(in_plane(dropped)), 0);
  EXPECT_NEAR(in_plane(end).norm(), in_plane(start).norm(), 1e-12);
  // The handles were remade where the edited path puts them.
  EXPECT_LT((handles->position(1) - end).norm(), 1e-12);

  QUndoStack* undo = doc->undoStack();
  const Scene dragged = doc->scene();
  undo->undo();
  EXPECT_EQ(doc->scene(), original);
  undo->redo();
  EXPECT_EQ(doc->scene(), dragged);

  const std::string file = TempFile("dragged");
  ASSERT_TRUE(window.saveScene(QString::fromStdString(file)));
  const Scene reread = ReadScene(file);
  std::filesystem::remove(file);
  EXPECT_EQ(reread, dragged);
}

TEST_F(Widgets, MovesAreTypedWithUnitsAndReadByTheSceneReader) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kStages, 2));  // T: a slide
  MoveEditor* moves = window.stages()->moves();
  ASSERT_EQ(moves->stage(), 2);
  ASSERT_EQ(moves->currentMove(), 0);
  ASSERT_TRUE(moves->setPath("line", "2 cm, 0, 10 mm")) << moves->message().toStdString();
  EXPECT_EQ(std::get<LinePath>(doc->scene().stages[2].moves[0].path).by, (Vec3{0.02, 0, 0.01}));
  EXPECT_EQ(window.pathHandles()->count(), 1);

  // Two components: the reader's message, naming the key; nothing changes.
  const Scene before = doc->scene();
  EXPECT_FALSE(moves->setPath("line", "2 cm, 0"));
  EXPECT_NE(moves->message().toStdString().find("by"), std::string::npos)
      << moves->message().toStdString();
  EXPECT_EQ(doc->scene(), before);
  EXPECT_FALSE(moves->setPath("arc", "0, 0, 0", "0, 1, 0", "90 kg"));
  EXPECT_EQ(doc->scene(), before);

  ASSERT_TRUE(moves->setPath("keyframes", "0, 0, 1 cm; 1 cm, 0, 1 cm; 2 cm, 0, 0", "smooth"))
      << moves->message().toStdString();
  const auto& keys = std::get<KeyframesPath>(doc->scene().stages[2].moves[0].path);
  ASSERT_EQ(keys.points.size(), 3u);
  EXPECT_EQ(keys.points[1], (Vec3{0.01, 0, 0.01}));
  EXPECT_EQ(keys.interpolation, Interpolation::kSmooth);
  EXPECT_EQ(window.pathHandles()->count(), 3);  // one per keyframe

  // A second move in the same stage carries the table (added 5 cm up, then
  // typed 1 cm down); removed, and the removal undone.
  ASSERT_TRUE(moves->addMove("obstacle table")) << moves->message().toStdString();
  ASSERT_EQ(doc->scene().stages[2].moves.size(), 2u);
  EXPECT_EQ(doc->scene().stages[2].moves[1].obstacle, "table");
  // Its handle: the table's point (z = −c) carried 5 cm up.
  ASSERT_EQ(window.pathHandles()->count(), 1);
  EXPECT_LT((window.pathHandles()->position(0) - Eigen::Vector3d(0, 0, 0.05 - 0.02345e-2)).norm(),
            1e-12);
  ASSERT_TRUE(moves->setPath("line", "0, 0, -1 cm"));
  ASSERT_TRUE(moves->removeSelected());
  EXPECT_EQ(doc->scene().stages[2].moves.size(), 1u);
  doc->undoStack()->undo();
  EXPECT_EQ(std::get<LinePath>(doc->scene().stages[2].moves[1].path).by, (Vec3{0, 0, -0.01}));
}

TEST_F(Widgets, StagesAreAddedAndReleaseGrippersByTheReadersRules) {
  MainWindow window;
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  StagesPanel* stages = window.stages();
  const size_t n = doc->scene().stages.size();
  ASSERT_TRUE(stages->addStage("move")) << stages->message().toStdString();
  ASSERT_EQ(doc->scene().stages.size(), n + 1);
  EXPECT_EQ(doc->scene().stages.back().kind, StageKind::kMove);
  EXPECT_EQ(doc->scene().stages.back().moves.at(0).gripper, "end");
  ASSERT_TRUE(stages->addStage("hold"));
  EXPECT_EQ(stages->list()->currentRow(), static_cast<int>(n + 1));
  ASSERT_TRUE(stages->setRelease("end")) << stages->message().toStdString();
  EXPECT_EQ(doc->scene().stages.back().release, std::vector<std::string>{"end"});
  EXPECT_FALSE(stages->setRelease("nobody"));
  EXPECT_NE(stages->message().toStdString().find("no gripper is named 'nobody'"), std::string::npos)
      << stages->message().toStdString();
  // Released before a stage that moves it: refused.
  stages->list()->setCurrentRow(static_cast<int>(n + 1));
  const Scene before = doc->scene();
  EXPECT_FALSE(stages->moveSelected(-1));  // the releasing hold before the move
  EXPECT_NE(stages->message().toStdString().find("was released in"), std::string::npos)
      << stages->message().toStdString();
  EXPECT_EQ(doc->scene(), before);
}

TEST_F(Widgets, NodesPickedInTheViewBecomeAGrippersSelection) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  QTest::qWait(200);
  SceneDocument* doc = window.document();
  const ShellModel model = BuildShellModel(doc->scene());
  // A point of the strip's surface just inside its top edge at x = 5 cm;
  // the node nearest it is the edge node there.
  const Eigen::Vector3d target(0.0502, 0.009, 0.0);
  Eigen::Index expected = 0;
  (model.reference.positions.rowwise() - target.transpose())
      .rowwise()
      .squaredNorm()
      .minCoeff(&expected);
  ASSERT_LT((model.reference.positions.row(expected) - Eigen::RowVector3d(0.05, 0.01, 0)).norm(),
            1e-9);

  window.viewport()->setPickMode(true);
  const QPoint at = OnScreen(window.viewport(), target);
  QTest::mouseClick(window.viewport(), Qt::LeftButton, {}, at);
  ASSERT_EQ(window.pickedNodes(), std::vector<int>{static_cast<int>(expected)});
  // A second click on it unpicks it; a third picks it again.
  QTest::mouseClick(window.viewport(), Qt::LeftButton, {}, at);
  EXPECT_TRUE(window.pickedNodes().empty());
  QTest::mouseClick(window.viewport(), Qt::LeftButton, {}, at);
  ASSERT_EQ(window.pickedNodes().size(), 1u);
  window.viewport()->setPickMode(false);
  if (getenv("DRAPE_PICK_SHOT")) {  // to look at the picked node's marker
    QTest::qWait(100);
    window.viewport()->grabFramebuffer().save(getenv("DRAPE_PICK_SHOT"));
  }

  // One node is held as the point where it is (any mesh finds it): the
  // engine's gripper holds exactly the picked node.
  HoldsPanel* grippers = window.grippers();
  const size_t before = doc->scene().grippers.size();
  ASSERT_TRUE(grippers->add("picked", 1)) << grippers->message().toStdString();
  ASSERT_EQ(doc->scene().grippers.size(), before + 1);
  const Gripper& g = doc->scene().grippers.back();
  EXPECT_EQ(g.hold, Fixity::kClamp);
  EXPECT_EQ(std::get<PointSelection>(g.select.shape).at, (Vec2{0.05, 0.01}));
  EXPECT_EQ(BuildShellModel(doc->scene()).grippers.back().nodes,
            std::vector<int>{static_cast<int>(expected)});

  // Two nodes are held by their numbers.
  const Eigen::Vector3d below(0.0502, -0.009, 0.0);
  Eigen::Index second = 0;
  (model.reference.positions.rowwise() - below.transpose())
      .rowwise()
      .squaredNorm()
      .minCoeff(&second);
  window.viewport()->setPickMode(true);
  QTest::mouseClick(window.viewport(), Qt::LeftButton, {}, OnScreen(window.viewport(), below));
  window.viewport()->setPickMode(false);
  ASSERT_EQ(window.pickedNodes(),
            (std::vector<int>{static_cast<int>(expected), static_cast<int>(second)}));
  ASSERT_TRUE(window.supports()->add("picked", 0)) << window.supports()->message().toStdString();
  EXPECT_EQ(std::get<NodesSelection>(doc->scene().supports.back().select.shape).nodes,
            window.pickedNodes());
  // A new mesh puts those numbers elsewhere: the workbench says so.
  window.properties()->elementsX()->setValue(100);
  emit window.properties()->elementsX()->editingFinished();
  bool warned = false;
  for (const QMessageBox* box : window.findChildren<QMessageBox*>())
    warned = warned || box->text().contains("hold nodes by their numbers");
  EXPECT_TRUE(warned);
  EXPECT_TRUE(window.pickedNodes().empty());  // picked on the old mesh
  doc->undoStack()->undo();
  doc->undoStack()->undo();

  // Removing the gripper the stages move is refused with the reader's words.
  grippers->list()->setCurrentRow(0);
  EXPECT_FALSE(grippers->removeSelected());
  EXPECT_NE(grippers->message().toStdString().find("end"), std::string::npos)
      << grippers->message().toStdString();
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene().grippers.size(), before);
}

}  // namespace
}  // namespace drape
