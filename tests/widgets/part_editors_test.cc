// The workbench's editors of the scene's parts, driven as a user would: the
// fabric's outline, its membrane, obstacles (typed as JSON and dragged in
// the view), loads and probes. Each edit is checked against geometry or the
// scene reader's own reading, and undone.
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
#include "support/mesh_area.h"
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

using test::MeshArea;

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

  // The barrier law: its distance field takes the penalty's place, friction
  // stays editable, and switching back (undo) restores the penalty.
  EXPECT_TRUE(panel->penalty()->isEnabled());
  EXPECT_FALSE(panel->barrierDistance()->isEnabled());
  ASSERT_TRUE(panel->setContactLaw("barrier")) << panel->message().toStdString();
  EXPECT_EQ(doc->scene().contact->law, ContactLaw::kBarrier);
  EXPECT_FALSE(doc->scene().contact->penalty.has_value());
  EXPECT_EQ(panel->contactLaw()->currentText().toStdString(), "barrier");
  EXPECT_FALSE(panel->penalty()->isEnabled());
  EXPECT_TRUE(panel->barrierDistance()->isEnabled());
  EXPECT_EQ(panel->barrierDistance()->text().toStdString(), "auto");
  ASSERT_TRUE(panel->setBarrierDistance("0.1 mm")) << panel->message().toStdString();
  EXPECT_DOUBLE_EQ(*doc->scene().contact->barrier_distance, 1e-4);
  EXPECT_FALSE(panel->setBarrierDistance("-1 mm"));
  EXPECT_NE(panel->message().toStdString().find("contact.barrier_distance"), std::string::npos)
      << panel->message().toStdString();
  ASSERT_TRUE(panel->setContact("auto", "0.25")) << panel->message().toStdString();
  EXPECT_EQ(doc->scene().contact->friction, 0.25);
  EXPECT_EQ(doc->scene().contact->law, ContactLaw::kBarrier);
  for (int k = 0; k < 3; ++k) doc->undoStack()->undo();
  EXPECT_EQ(doc->scene().contact->law, ContactLaw::kPenalty);
  EXPECT_EQ(panel->contactLaw()->currentText().toStdString(), "penalty");
  EXPECT_TRUE(panel->penalty()->isEnabled());

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

}  // namespace
}  // namespace drape
