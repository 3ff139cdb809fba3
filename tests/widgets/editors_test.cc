// The workbench's scene editors driven as a user would: a path handle
// dragged with the mouse in the viewport, nodes picked by clicking the
// fabric, moves and stages typed in. Each edit is checked against geometry
// computed here, undone, redone, and survives save and reopen.
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

// Where a world point is drawn in the viewport, in widget coordinates.
QPoint OnScreen(VtkViewport* viewport, const Eigen::Vector3d& p) {
  vtkRenderer* r = viewport->renderWindow()->GetRenderers()->GetFirstRenderer();
  r->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  r->WorldToDisplay();
  double d[3];
  r->GetDisplayPoint(d);
  const double dpr = viewport->devicePixelRatioF();
  return QPoint(qRound(d[0] / dpr), qRound(viewport->height() - (d[1] + 1) / dpr));
}

void Mouse(
    QWidget* w, QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons held) {
  QMouseEvent event(type, QPointF(at), QPointF(w->mapToGlobal(at)), button, held, Qt::NoModifier);
  QApplication::sendEvent(w, &event);
}

// Press, ten moves, release: what a hand does.
void Drag(QWidget* w, QPoint from, QPoint to) {
  Mouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
  for (int k = 1; k <= 10; ++k)
    Mouse(w, QEvent::MouseMove, from + (to - from) * k / 10, Qt::NoButton, Qt::LeftButton);
  Mouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

std::string TempFile(const std::string& stem) {
  return (std::filesystem::temp_directory_path() /
          (stem + "-" + std::to_string(getpid()) + ".json"))
      .string();
}

QString StripFold() {
  return QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
}

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

// Area of a quad mesh (each quad as two triangles; exact for planar quads).
double MeshArea(const ShellModel& model) {
  double area = 0;
  const auto& x = model.reference.positions;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const auto q = model.mesh.quads.row(e);
    const Eigen::Vector3d a = x.row(q(0)), b = x.row(q(1)), c = x.row(q(2)), d = x.row(q(3));
    area += 0.5 * ((b - a).cross(c - a).norm() + (c - a).cross(d - a).norm());
  }
  return area;
}

TEST_F(Widgets, OutlinesAreEditedAsRectangleDiskOrPolygon) {
  MainWindow window;
  ASSERT_TRUE(
      window.openScene(QString::fromStdString((test::ScenesDir() / "block-drape.json").string())));
  SceneDocument* doc = window.document();
  PropertyPanel* panel = window.properties();
  const Scene original = doc->scene();

  ASSERT_TRUE(panel->setOutline("rectangle", "30 cm, 10 cm", "1 cm, 0"))
      << panel->fabricMessage().toStdString();
  const auto& r = std::get<RectangleOutline>(doc->scene().fabric.outline);
  EXPECT_EQ(r.size, (Vec2{0.3, 0.1}));
  EXPECT_EQ(r.center, (Vec2{0.01, 0}));
  ShellModel model = BuildShellModel(doc->scene());
  EXPECT_NEAR(MeshArea(model), 0.03, 1e-12);

  // The part hangs from its corners: a disk has none, and says so.
  EXPECT_FALSE(panel->setOutline("disk", "10 cm"));
  EXPECT_NE(panel->fabricMessage().toStdString().find("a disk has no corners"), std::string::npos)
      << panel->fabricMessage().toStdString();
  HoldsPanel* supports = window.supports();
  ASSERT_TRUE(supports->add("point", 0, 0.0, 0.0)) << supports->message().toStdString();
  supports->list()->setCurrentRow(0);
  ASSERT_TRUE(supports->removeSelected()) << supports->message().toStdString();

  // A disk of radius 15 cm (the probes stay on it) is meshed by size: its
  // boundary nodes lie on the circle and its area tends to π r² (less the
  // chords' segments).
  ASSERT_TRUE(panel->setOutline("disk", "15 cm")) << panel->fabricMessage().toStdString();
  ASSERT_TRUE(panel->setElementSize("1.5 cm")) << panel->fabricMessage().toStdString();
  EXPECT_EQ(*doc->scene().fabric.mesh.size, 0.015);
  model = BuildShellModel(doc->scene());
  EXPECT_NEAR(model.reference.positions.rowwise().norm().maxCoeff(), 0.15, 1e-9);
  EXPECT_NEAR(MeshArea(model), M_PI * 0.0225, 0.01 * M_PI * 0.0225);
  EXPECT_LT(MeshArea(model), M_PI * 0.0225);
  EXPECT_EQ(panel->meshInfo()->text().toStdString(),
            std::to_string(model.NodeCount()) + " nodes, " +
                std::to_string(model.mesh.ElementCount()) + " elements, " +
                std::to_string(5 * model.NodeCount()) + " DOFs");

  // A triangle: base 40 cm, height 30 cm.
  ASSERT_TRUE(panel->setOutline("polygon", "-20 cm, -10 cm; 20 cm, -10 cm; 0, 20 cm"))
      << panel->fabricMessage().toStdString();
  EXPECT_EQ(std::get<PolygonOutline>(doc->scene().fabric.outline).vertices.size(), 3u);
  EXPECT_NEAR(MeshArea(BuildShellModel(doc->scene())), 0.06, 1e-9);

  // Wrong text: the reader's message, naming the key; nothing changes.
  const Scene before = doc->scene();
  EXPECT_FALSE(panel->setOutline("disk", "10 kg"));
  EXPECT_NE(panel->fabricMessage().toStdString().find("radius"), std::string::npos)
      << panel->fabricMessage().toStdString();
  EXPECT_FALSE(panel->setOutline("polygon", "0, 0; 1 cm, 0"));
  EXPECT_NE(panel->fabricMessage().toStdString().find("at least 3 vertices"), std::string::npos)
      << panel->fabricMessage().toStdString();
  EXPECT_EQ(doc->scene(), before);

  // An imperfection of 0.1 mm, node by node: every node within it, and the
  // flat part no longer flat.
  ASSERT_TRUE(panel->setImperfection("0.1 mm", 7, "nodal")) << panel->fabricMessage().toStdString();
  ASSERT_TRUE(doc->scene().fabric.imperfection.has_value());
  EXPECT_EQ(doc->scene().fabric.imperfection->seed, 7u);
  const Eigen::VectorXd z = BuildShellModel(doc->scene()).reference.positions.col(2);
  EXPECT_LE(z.cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_GT(z.cwiseAbs().maxCoeff(), 0.5e-4);
  EXPECT_FALSE(panel->setImperfection("0.1 kg", 7, "nodal"));
  EXPECT_NE(panel->fabricMessage().toStdString().find("amplitude"), std::string::npos)
      << panel->fabricMessage().toStdString();
  ASSERT_TRUE(panel->setImperfection("0", 7, "nodal"));
  EXPECT_FALSE(doc->scene().fabric.imperfection.has_value());

  QUndoStack* undo = doc->undoStack();
  while (undo->canUndo()) undo->undo();
  EXPECT_EQ(doc->scene(), original);
}

TEST_F(Widgets, ObstaclesAreAddedEditedAsJsonAndDraggedInTheView) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  ObstaclesPanel* panel = window.obstacles();
  const Scene original = doc->scene();
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kObstacles));
  ASSERT_TRUE(panel->add("sphere")) << panel->message().toStdString();
  ASSERT_EQ(doc->scene().obstacles.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<SphereShape>(doc->scene().obstacles[1].shape));

  // Edited as the scene file writes it, with units.
  ASSERT_TRUE(panel->applyText(
      R"({"name": "ball", "sphere": {"center": [0, 0, "-4 cm"], "radius": "3 cm"}})"))
      << panel->message().toStdString();
  const auto& ball = std::get<SphereShape>(doc->scene().obstacles[1].shape);
  EXPECT_DOUBLE_EQ(ball.radius, 0.03);
  EXPECT_DOUBLE_EQ(ball.center[2], -0.04);
  EXPECT_EQ(doc->scene().obstacles[1].name, "ball");
  // Wrong text: not JSON, or a value the reader refuses; nothing changes.
  const Scene before = doc->scene();
  EXPECT_FALSE(panel->applyText(R"({"name": "ball", "sphere": )"));
  EXPECT_NE(panel->message().toStdString().find("not JSON"), std::string::npos);
  EXPECT_FALSE(panel->applyText(R"({"name": "ball", "sphere": {"center": [0, 0], "radius": 1}})"));
  EXPECT_NE(panel->message().toStdString().find("obstacles[1]"), std::string::npos)
      << panel->message().toStdString();
  EXPECT_EQ(doc->scene(), before);

  // Its handle sits at the centre; dragged, the ball moves with it.
  QTest::qWait(200);
  DragHandles* handle = window.obstacleHandles();
  ASSERT_EQ(handle->count(), 1);
  EXPECT_LT((handle->position(0) - Eigen::Vector3d(0, 0, -0.04)).norm(), 1e-15);
  const QPoint from = OnScreen(window.viewport(), handle->position(0));
  Drag(window.viewport(), from, from + QPoint(50, -30));
  const Eigen::Vector3d dropped = handle->position(0);
  EXPECT_GT((dropped - Eigen::Vector3d(0, 0, -0.04)).norm(), 1e-3) << "the drag did not move it";
  QTest::qWait(50);
  EXPECT_LT((*ObstacleAnchor(doc->scene().obstacles[1]) - dropped).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(std::get<SphereShape>(doc->scene().obstacles[1].shape).radius, 0.03);

  // The handle is there while the obstacles' editor is.
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kFabric));
  QTest::qWait(50);
  EXPECT_EQ(handle->count(), 0);
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kObstacles, 1));
  QTest::qWait(50);
  EXPECT_EQ(handle->count(), 1);

  // The contact: penalty and friction, read by the reader.
  ASSERT_TRUE(panel->setContact("auto", "0.3")) << panel->message().toStdString();
  ASSERT_TRUE(doc->scene().contact.has_value());
  EXPECT_EQ(doc->scene().contact->friction, 0.3);
  EXPECT_FALSE(doc->scene().contact->penalty.has_value());
  ASSERT_TRUE(panel->setContact("2e8 N/m^3", "0.3"));
  EXPECT_EQ(*doc->scene().contact->penalty, 2e8);
  EXPECT_FALSE(panel->setContact("auto", "-1"));
  EXPECT_NE(panel->message().toStdString().find("must not be negative"), std::string::npos)
      << panel->message().toStdString();
  EXPECT_FALSE(panel->setContact("2e8 N", "0.3"));  // not a penalty per area
  EXPECT_EQ(doc->scene().contact->friction, 0.3);
  // Self-contact: a check box (on by default), undoable, and kept when the
  // penalty changes.
  EXPECT_TRUE(panel->selfContact()->isChecked());
  panel->selfContact()->setChecked(false);
  EXPECT_FALSE(doc->scene().contact->self);
  ASSERT_TRUE(panel->setContact("auto", "0.2"));
  EXPECT_FALSE(doc->scene().contact->self);
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  EXPECT_TRUE(doc->scene().contact->self);
  EXPECT_TRUE(panel->selfContact()->isChecked());

  // Removing the table a stage does not move: allowed, and undone.
  panel->list()->setCurrentRow(0);
  ASSERT_TRUE(panel->removeSelected()) << panel->message().toStdString();
  EXPECT_EQ(doc->scene().obstacles.size(), 1u);
  QUndoStack* undo = doc->undoStack();
  while (undo->canUndo()) undo->undo();
  EXPECT_EQ(doc->scene(), original);
}

TEST_F(Widgets, ProbesAreAddedAndPlottedDuringARun) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  ProbesPanel* probes = window.probes();
  const size_t before = doc->scene().probes.size();
  ASSERT_TRUE(probes->add(0.05, 0.0)) << probes->message().toStdString();
  ASSERT_EQ(doc->scene().probes.size(), before + 1);
  EXPECT_EQ(doc->scene().probes.back().at, (Vec2{0.05, 0.0}));
  // Off the 20 × 2 cm strip: the engine's message.
  EXPECT_FALSE(probes->add(0.5, 0.0));
  EXPECT_NE(probes->message().toStdString().find("outside the fabric"), std::string::npos)
      << probes->message().toStdString();
  EXPECT_EQ(doc->scene().probes.size(), before + 1);

  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  QTest::qWait(50);
  const int steps = window.stepCount();
  // One point per step for every probe; the last is the last step's.
  for (int p = 0; p < static_cast<int>(before + 1); ++p)
    EXPECT_EQ(window.probePlot()->points(p), steps);
  const auto& last = window.step(steps);
  ASSERT_EQ(last.probes.size(), before + 1);
  EXPECT_EQ(window.probePlot()->lastHeight(static_cast<int>(before)), last.probes.back().value.z());
  // Folded in half, the point 5 cm right of the middle lies on the table,
  // whose surface is half a thickness below z = 0: its midsurface is at 0,
  // less the penalty's penetration (held under 0.5 % of h = 0.469 mm).
  EXPECT_NEAR(last.probes.back().value.z(), 0.0, 0.005 * 0.469e-3);
  EXPECT_EQ(window.residualPlot()->points(), static_cast<int>(last.residuals.size()));
}

// The editor whose tab is up in the tabbed dock area that holds `title`
// (a dock tabbed behind another still says isVisible()).
QString RaisedTab(const QMainWindow& window, const QString& title) {
  for (const QTabBar* bar : window.findChildren<QTabBar*>())
    for (int i = 0; i < bar->count(); ++i)
      if (bar->tabText(i) == title) return bar->tabText(bar->currentIndex());
  return {};
}

TEST_F(Widgets, TheSceneTreeBringsUpEachPartsEditor) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  ModelTree* tree = window.tree();
  const Scene& scene = window.document()->scene();
  EXPECT_EQ(tree->item(ModelTree::Part::kStages)->childCount(),
            static_cast<int>(scene.stages.size()));
  EXPECT_EQ(tree->item(ModelTree::Part::kStages, 1)->childCount(), 1);  // R's move
  EXPECT_EQ(tree->item(ModelTree::Part::kGrippers, 0)->text(0).toStdString(), "end");
  tree->setCurrentItem(tree->item(ModelTree::Part::kGrippers, 0));
  QTest::qWait(20);
  EXPECT_EQ(RaisedTab(window, "Grippers").toStdString(), "Grippers");
  EXPECT_EQ(window.grippers()->list()->currentRow(), 0);
  tree->setCurrentItem(tree->item(ModelTree::Part::kStages, 2));
  QTest::qWait(20);
  EXPECT_EQ(RaisedTab(window, "Stages").toStdString(), "Stages");
  EXPECT_EQ(window.stages()->list()->currentRow(), 2);
  // Edits show in the tree.
  ASSERT_TRUE(window.stages()->addStage("hold"));
  EXPECT_EQ(tree->item(ModelTree::Part::kStages)->childCount(),
            static_cast<int>(scene.stages.size()));
}

TEST_F(Widgets, CameraViewsLookWhereTheirNamesSay) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  auto direction = [&] {
    double d[3];
    window.viewport()
        ->renderWindow()
        ->GetRenderers()
        ->GetFirstRenderer()
        ->GetActiveCamera()
        ->GetDirectionOfProjection(d);
    return Eigen::Vector3d(d[0], d[1], d[2]);
  };
  ASSERT_TRUE(window.setCamera("top"));
  EXPECT_LT((direction() - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  ASSERT_TRUE(window.setCamera("front"));
  EXPECT_NEAR(direction().z(), 0.0, 1e-9);  // level
  EXPECT_FALSE(window.setCamera("below"));
  EXPECT_EQ(window.viewport()->renderWindow()->GetRenderers()->GetNumberOfItems(), 1);
}

TEST_F(Widgets, TheMembraneIsIsotropicOrOrthotropic) {
  MainWindow window;
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  PropertyPanel* panel = window.properties();
  const Scene original = doc->scene();
  const auto iso = std::get<IsotropicMembrane>(original.material.membrane);
  ASSERT_TRUE(panel->setOrthotropic(true)) << panel->materialMessage().toStdString();
  auto ortho = [&] { return std::get<OrthotropicMembrane>(doc->scene().material.membrane); };
  // The same material: G = E / 2(1 + ν).
  EXPECT_EQ(ortho().e1, iso.youngs_modulus);
  EXPECT_EQ(ortho().e2, iso.youngs_modulus);
  EXPECT_EQ(ortho().nu12, iso.poisson_ratio);
  EXPECT_DOUBLE_EQ(ortho().g12, iso.youngs_modulus / (2 * (1 + iso.poisson_ratio)));

  QLineEdit* e2 = panel->e2()->edit();
  e2->setText("100 kPa");
  emit e2->editingFinished();
  EXPECT_DOUBLE_EQ(ortho().e2, 1e5);
  // ν₁₂² E₂/E₁ ≥ 1 is not a stable law: the reader's message, the value back.
  QLineEdit* nu = panel->nu12()->edit();
  nu->setText("5");
  emit nu->editingFinished();
  EXPECT_NE(panel->materialMessage().toStdString().find("nu12"), std::string::npos)
      << panel->materialMessage().toStdString();
  EXPECT_EQ(ortho().nu12, iso.poisson_ratio);
  EXPECT_EQ(nu->text().toStdString(), QString::number(iso.poisson_ratio).toStdString());

  ASSERT_TRUE(panel->setOrthotropic(false));
  const auto back = std::get<IsotropicMembrane>(doc->scene().material.membrane);
  EXPECT_EQ(back.youngs_modulus, iso.youngs_modulus);
  QUndoStack* undo = doc->undoStack();
  while (undo->canUndo()) undo->undo();
  EXPECT_EQ(doc->scene(), original);
}

TEST_F(Widgets, LoadsAreTypedWithUnitsAndAppliedByALoadStage) {
  MainWindow window;
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  LoadsPanel* loads = window.loads();
  const Scene original = doc->scene();
  // 2 gf down on the strip's middle, as a point (the node found there).
  ASSERT_TRUE(loads->add("point", "0, 0, -2 gf", "0, 0, 0", 0.0, 0.0))
      << loads->message().toStdString();
  ASSERT_EQ(doc->scene().loads.size(), 1u);
  const PointLoad& load = doc->scene().loads[0];
  EXPECT_DOUBLE_EQ(load.force[2], -2 * 9.80665e-3);
  EXPECT_EQ(std::get<PointSelection>(load.select.shape).at, (Vec2{0, 0}));
  EXPECT_EQ(window.tree()->item(ModelTree::Part::kLoads)->childCount(), 1);
  // A force with a moment's unit: the reader's message names the key.
  EXPECT_FALSE(loads->setForce("0, 0, -2 gf*cm", "0, 0, 0"));
  EXPECT_NE(loads->message().toStdString().find("loads[0].force"), std::string::npos)
      << loads->message().toStdString();
  ASSERT_TRUE(loads->setForce("0, 0, -1 N", "0, 0.01, 0"));
  EXPECT_EQ(doc->scene().loads[0].moment, (Vec3{0, 0.01, 0}));
  // A load stage applies it; the engine takes the scene.
  ASSERT_TRUE(window.stages()->addStage("load")) << window.stages()->message().toStdString();
  EXPECT_EQ(doc->scene().stages.back().kind, StageKind::kLoad);
  QUndoStack* undo = doc->undoStack();
  while (undo->canUndo()) undo->undo();
  EXPECT_EQ(doc->scene(), original);
}

TEST_F(Widgets, TheSelectedLoadShowsItsRuleAndPoint) {
  MainWindow window;
  ASSERT_TRUE(window.openScene(StripFold()));
  LoadsPanel* loads = window.loads();
  ASSERT_TRUE(loads->add("point", "0, 0, -2 gf", "0, 0, 0", 0.05, 0.0))
      << loads->message().toStdString();
  ASSERT_TRUE(loads->add("right", "0, 0, -1 gf")) << loads->message().toStdString();
  EXPECT_EQ(loads->rule()->rule()->currentText().toStdString(), "right");
  loads->list()->setCurrentRow(0);
  EXPECT_EQ(loads->rule()->rule()->currentText().toStdString(), "point");
  const auto at = TypedPoint(loads->rule()->point()->text());  // in the shown units
  EXPECT_NEAR(at[0], 0.05, 1e-12);
  EXPECT_NEAR(at[1], 0.0, 1e-12);
  loads->list()->setCurrentRow(1);
  EXPECT_EQ(loads->rule()->rule()->currentText().toStdString(), "right");
}

TEST_F(Widgets, SolverSettingsComeFromPresetsOrFields) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  PropertyPanel* panel = window.properties();
  QComboBox* preset = panel->solverPreset();
  // The strip fold's own settings are no preset.
  EXPECT_EQ(preset->currentData().toString().toStdString(), "custom");
  EXPECT_EQ(panel->meshInfo()->text().toStdString(), "243 nodes, 160 elements, 1215 DOFs");
  preset->setCurrentIndex(preset->findData("draft"));
  emit preset->activated(preset->currentIndex());
  ASSERT_TRUE(doc->scene().solver.preset.has_value());
  EXPECT_EQ(*doc->scene().solver.preset, SolverPreset::kDraft);
  EXPECT_EQ(doc->scene().solver.tolerance, 1e-4);
  EXPECT_EQ(doc->scene().solver.target_iterations, 6);
  EXPECT_EQ(doc->scene().solver.mesh_scale, 0.5);
  EXPECT_EQ(panel->tolerance()->edit()->text().toStdString(), "0.0001");
  // Half the 80 x 2 strip's elements along it; its width of two stays: 40 x 2.
  EXPECT_EQ(panel->meshInfo()->text().toStdString(),
            "solved on 123 nodes, 80 elements, 615 DOFs: 0.5 × the element counts above "
            "(accuracy draft)");
  EXPECT_EQ(doc->scene().fabric.mesh.elements, (std::array<int, 2>{80, 2}));
  // Undo brings the scene's own settings back in one step.
  doc->undoStack()->undo();
  EXPECT_FALSE(doc->scene().solver.preset.has_value());
  EXPECT_EQ(doc->scene().solver.mesh_scale, 1.0);
  EXPECT_EQ(doc->scene().solver.tolerance, 1e-6);
  doc->undoStack()->redo();
  // A preset's number changed by hand makes the settings custom; the mesh stays.
  QLineEdit* tolerance = panel->tolerance()->edit();
  tolerance->setText("1e-6");
  emit tolerance->editingFinished();
  EXPECT_EQ(doc->scene().solver.tolerance, 1e-6);
  EXPECT_EQ(preset->currentData().toString().toStdString(), "custom");
  EXPECT_FALSE(doc->scene().solver.preset.has_value());
  EXPECT_EQ(doc->scene().solver.mesh_scale, 0.5);
  // "custom" from the menu: the scene's own mesh again.
  preset->setCurrentIndex(preset->findData("custom"));
  emit preset->activated(preset->currentIndex());
  EXPECT_EQ(doc->scene().solver.mesh_scale, 1.0);
  // The error estimate: off by default, an undoable switch.
  EXPECT_FALSE(panel->errorEstimate()->isChecked());
  panel->errorEstimate()->setChecked(true);
  EXPECT_TRUE(doc->scene().solver.error_estimate);
  doc->undoStack()->undo();
  EXPECT_FALSE(doc->scene().solver.error_estimate);
  EXPECT_FALSE(panel->errorEstimate()->isChecked());
  tolerance->setText("2");
  emit tolerance->editingFinished();
  EXPECT_EQ(panel->tolerance()->message().toStdString(), "must lie in (0, 1)");
  EXPECT_EQ(doc->scene().solver.tolerance, 1e-6);
  panel->maxSteps()->setValue(250);
  emit panel->maxSteps()->editingFinished();
  EXPECT_EQ(doc->scene().solver.max_steps, 250);
  panel->targetIterations()->setValue(4);
  emit panel->targetIterations()->editingFinished();
  EXPECT_EQ(doc->scene().solver.target_iterations, 4);
  // The run's time limit: none by default, seconds when set, undoable.
  EXPECT_EQ(panel->timeLimit()->text().toStdString(), "none");
  panel->timeLimit()->setValue(90);
  emit panel->timeLimit()->editingFinished();
  ASSERT_TRUE(doc->scene().solver.max_wall_s.has_value());
  EXPECT_EQ(*doc->scene().solver.max_wall_s, 90.0);
  EXPECT_EQ(panel->timeLimit()->text().toStdString(), "90.0 s");
  doc->undoStack()->undo();
  EXPECT_FALSE(doc->scene().solver.max_wall_s.has_value());
  EXPECT_EQ(panel->timeLimit()->text().toStdString(), "none");
  // Mesh sequencing: the strip fold moves a gripper in three stages, so it
  // is refused with the reader's message and the field goes back.
  EXPECT_EQ(panel->sequencing()->text().toStdString(), "off");
  panel->sequencing()->setValue(2);
  emit panel->sequencing()->editingFinished();
  EXPECT_EQ(doc->scene().solver.sequencing, 1);
  EXPECT_EQ(panel->sequencing()->value(), 1);
  EXPECT_NE(panel->materialMessage().toStdString().find("solver.sequencing"), std::string::npos)
      << panel->materialMessage().toStdString();
  // What happens at a bifurcation: an undoable choice, shown back.
  QComboBox* branching = panel->branching();
  EXPECT_EQ(branching->currentData().toString().toStdString(), "stable");
  branching->setCurrentIndex(branching->findData("fundamental"));
  emit branching->activated(branching->currentIndex());
  EXPECT_EQ(doc->scene().solver.branching, Branching::kFundamental);
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene().solver.branching, Branching::kStable);
  EXPECT_EQ(branching->currentData().toString().toStdString(), "stable");
}

// A run works on the scene it started with: no edit reaches the scene while
// it goes on — not from a dialog opened before it, not from a script.
TEST_F(Widgets, NothingEditsTheSceneWhileARunWorksOnIt) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  SceneDocument* doc = window.document();
  MaterialDialog dialog(doc);  // opened before the run
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  window.pauseOrResume();
  const Scene running = doc->scene();
  dialog.library()->setCurrentText("cotton-twill");
  EXPECT_FALSE(dialog.applyLibrary());
  EXPECT_NE(dialog.message().toStdString().find("a run is working on the scene"), std::string::npos)
      << dialog.message().toStdString();
  Scene thicker = running;
  thicker.material.thickness *= 2;
  QString problem;
  EXPECT_FALSE(doc->tryApply("thickness", thicker, &problem));
  doc->apply("thickness", thicker);
  EXPECT_EQ(doc->scene(), running);
  EXPECT_FALSE(window.properties()->isEnabled());
  window.stop();
  ASSERT_TRUE(finished.count() > 0 || finished.wait(30000));
  // Afterwards the same edits go through.
  EXPECT_TRUE(dialog.applyLibrary()) << dialog.message().toStdString();
  EXPECT_TRUE(doc->tryApply("thickness", thicker, &problem)) << problem.toStdString();
}

// Garbage typed into every field of every editor: each is refused, the
// scene stays as it was, nothing crashes.
TEST_F(Widgets, GarbageInAnyFieldChangesNothing) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(StripFold()));
  // Stage R's arc, so that the move's fields are filled and enabled.
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kStages, 1, 0));
  const Scene original = window.document()->scene();
  int fields = 0;
  for (const char* garbage : {"kg", "1e999 m", "nan", "-", "1, 2, 3, 4, 5", ";;", "\u2603"}) {
    for (QLineEdit* edit : window.findChildren<QLineEdit*>()) {
      if (!edit->isEnabled() || edit->isReadOnly()) continue;
      const QString before = edit->text();
      edit->setText(QString::fromUtf8(garbage));
      emit edit->editingFinished();
      ++fields;
      EXPECT_EQ(window.document()->scene(), original)
          << "'" << garbage << "' was taken by the field that showed '" << before.toStdString()
          << "'";
      // A field the user typed into keeps (or gets back) a valid text
      // after a refusal only where it has a value to go back to; reset
      // the others for the next round.
      if (edit->text() == QString::fromUtf8(garbage)) edit->setText(before);
    }
  }
  EXPECT_GT(fields, 40);  // every editor's fields were tried
}

}  // namespace
}  // namespace drape
