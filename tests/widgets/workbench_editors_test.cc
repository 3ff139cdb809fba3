// The workbench around its editors: the scene tree bringing up each part's
// editor, the camera's named views, solver settings from presets or fields,
// no edit while a run works on the scene, and garbage typed into any field
// changing nothing.
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

using test::StripFold;

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
  // Mesh sequencing: the strip fold moves a gripper in three stages, so a
  // factor is refused with the reader's message and the field goes back to
  // auto (the default: off for this scene); off is an undoable choice.
  EXPECT_EQ(panel->sequencing()->text().toStdString(), "auto");
  panel->sequencing()->setValue(2);
  emit panel->sequencing()->editingFinished();
  EXPECT_EQ(doc->scene().solver.sequencing, kAutoSequencing);
  EXPECT_EQ(panel->sequencing()->text().toStdString(), "auto");
  EXPECT_NE(panel->materialMessage().toStdString().find("solver.sequencing"), std::string::npos)
      << panel->materialMessage().toStdString();
  panel->sequencing()->setValue(1);
  EXPECT_EQ(panel->sequencing()->text().toStdString(), "off");
  emit panel->sequencing()->editingFinished();
  EXPECT_EQ(doc->scene().solver.sequencing, 1);
  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene().solver.sequencing, kAutoSequencing);
  EXPECT_EQ(panel->sequencing()->text().toStdString(), "auto");
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
  ASSERT_TRUE(dialog.chooseLibrary("cotton-twill"));
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
