// Forms placed by hand in the workbench: the dress form added from the list
// stands under the fabric's middle with the fabric laid just above it;
// moved, turned and scaled by its fields and dragged in the view, the
// fabric lying on it follows; each is one undo step, and undo puts the form
// and the fabric back. The expected heights come from the form's geometry:
// its neck is a flat cap at the top, s_z · 60 cm above where it stands, and
// the fabric stops a clearance of h/2 + max(1 mm, h) above it.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLineEdit>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <string>
#include <variant>

#include "core/model/obstacle_anchor.h"
#include "support/editor_input.h"
#include "support/test_paths.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/form_editor.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_editor.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/quantity_field.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_templates.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

constexpr double kFormHeight = 0.60;  // resources/forms/make_dress_form.py, neck cap

// Typed into the field and entered, as a hand does.
void Type(QLineEdit* field, const QString& text) {
  field->selectAll();
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

const MeshShape& Form(const SceneDocument& doc) {
  return std::get<MeshShape>(doc.scene().obstacles.back().shape);
}

TEST_F(Widgets, FormIsAddedMovedTurnedScaledAndTheFabricLiesOnIt) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.newFromTemplate(BlankTemplate().file));
  SceneDocument* doc = window.document();
  ObstaclesPanel* panel = window.obstacles();
  const Scene blank = doc->scene();
  const double h = blank.material.thickness;
  const double clearance = 0.5 * h + std::max(1e-3, h);

  // The list offers the dress form in its three sizes.
  QComboBox* kinds = panel->findChild<QComboBox*>();
  ASSERT_NE(kinds, nullptr);
  for (const char* size : {"Dress form, small", "Dress form, medium", "Dress form, large"})
    EXPECT_GE(kinds->findText(size), 0) << size;

  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kObstacles));
  ASSERT_TRUE(panel->add("Dress form, medium")) << panel->message().toStdString();
  ASSERT_EQ(doc->scene().obstacles.size(), 1u);
  EXPECT_EQ(Form(*doc).at, (Vec3{0, 0, 0}));  // under the 30 cm square's middle
  EXPECT_NEAR(doc->scene().fabric.elevation, kFormHeight + clearance, 1e-6);
  const Scene added = doc->scene();

  // Its fields: moved, then turned and scaled; the fabric follows each.
  FormEditor* form = panel->form();
  ASSERT_TRUE(form->isVisible());
  ASSERT_TRUE(form->place("10 cm, 5 cm, 2 cm", "0", "1")) << form->message().toStdString();
  EXPECT_EQ(Form(*doc).at, (Vec3{0.1, 0.05, 0.02}));
  EXPECT_NEAR(doc->scene().fabric.elevation, 0.02 + kFormHeight + clearance, 1e-6);
  Type(form->scale(), "1.1");  // typed in the field, as a user does
  Type(form->turn(), "30");
  EXPECT_EQ(Form(*doc).scale, (Vec3{1.1, 1.1, 1.1}));
  EXPECT_DOUBLE_EQ(Form(*doc).rotation_deg, 30);
  EXPECT_NEAR(doc->scene().fabric.elevation, 0.02 + 1.1 * kFormHeight + clearance, 1e-6);

  // A wrong scale: the reader's message with the key, nothing changed.
  const Scene before = doc->scene();
  EXPECT_FALSE(form->place("10 cm, 5 cm, 2 cm", "30", "-1"));
  // The edit in the editor's words beside the reader's, which names the key.
  EXPECT_EQ(form->message().toStdString().rfind("place form 1 — obstacles[0].mesh.scale: ", 0), 0u)
      << form->message().toStdString();
  EXPECT_TRUE(form->message().endsWith("found -1")) << form->message().toStdString();
  EXPECT_EQ(doc->scene(), before);

  // Dragged in the view by its handle: the form moves, the fabric with it.
  QTest::qWait(200);
  DragHandles* handle = window.obstacleHandles();
  ASSERT_EQ(handle->count(), 1);
  const QPoint from = test::OnScreen(window.viewport(), handle->position(0));
  test::Drag(window.viewport(), from, from + QPoint(0, -40));
  QTest::qWait(50);
  const double dz = Form(*doc).at[2] - 0.02;
  EXPECT_GT(std::abs(dz) + std::abs(Form(*doc).at[0] - 0.1), 1e-3) << "the drag did not move it";
  EXPECT_NEAR(
      doc->scene().fabric.elevation, Form(*doc).at[2] + 1.1 * kFormHeight + clearance, 1e-6);

  // Undone edit by edit: the form and the fabric where they were.
  QUndoStack* undo = doc->undoStack();
  for (int i = 0; i < 4; ++i) undo->undo();
  EXPECT_EQ(doc->scene(), added);
  undo->undo();
  EXPECT_EQ(doc->scene(), blank);
}

// A thickness typed as a bare number is read in metres: the scene takes it
// (it is a value, if no fabric's), and the material's group says so, with
// the field's name, the key and the millimetres likely meant. 0.5 mm is a
// fabric's, and the warning goes.
TEST_F(Widgets, ThicknessTypedWithoutAUnitIsSaidAsReadInMetres) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.newFromTemplate(BlankTemplate().file));
  MaterialEditor* material = window.properties()->material();
  EXPECT_TRUE(material->warnings().isEmpty()) << material->warnings().toStdString();
  Type(material->thickness()->edit(), "0.5");
  EXPECT_DOUBLE_EQ(window.document()->scene().material.thickness, 0.5)
      << material->message().toStdString() << " | "
      << material->thickness()->message().toStdString();
  EXPECT_EQ(material->warnings().split('\n').front().toStdString(),
            "thickness (material.thickness): 0.5 read as 0.5 m, thicker than any fabric "
            "(0.05–5 mm); did you mean 0.5 mm?");
  Type(material->thickness()->edit(), "0.5 mm");
  EXPECT_DOUBLE_EQ(window.document()->scene().material.thickness, 0.5e-3);
  EXPECT_TRUE(material->warnings().isEmpty()) << material->warnings().toStdString();
}

}  // namespace
}  // namespace drape
