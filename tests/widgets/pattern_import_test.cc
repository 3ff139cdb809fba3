// File ▸ Import pattern…, driven as a user would: a DXF written by ezdxf
// (tests/data/patterns/make_aama_dxf.py), its pieces listed, one placed on
// the table as the fabric, meshed with its cut-out, and undone.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QUndoStack>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/aama_patterns.h"
#include "support/drape_command.h"
#include "support/mesh_area.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_editor.h"
#include "ui/widgets/pattern_import_dialog.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/quantity_field.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/selection_rule.h"
#include "ui/widgets/view_controller.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

using test::MeshArea;

TEST_F(Widgets, APatternPieceIsImportedPlacedAndUndone) {
  test::TempDir dir("pattern-import");
  const std::filesystem::path dxf = dir / "shirt.dxf";
  test::MakeAamaPattern(dxf);
  // A sheet held at its corners, under its weight.
  std::ofstream(dir / "sheet.json") << R"({"drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": ["30 cm", "30 cm"]}}, "mesh": {"elements": [6, 6]}},
    "material": {"library": "cotton-twill"},
    "supports": [{"name": "corners", "select": {"corners": true}}],
    "stages": [{"name": "weight", "kind": "gravity"}]})";
  MainWindow window;
  ASSERT_TRUE(window.openScene(QString::fromStdString((dir / "sheet.json").string())));
  SceneDocument* doc = window.document();
  const Scene before = doc->scene();

  PatternImportDialog dialog(doc);
  dialog.file()->setText(QString::fromStdString(dxf.string()));
  ASSERT_TRUE(dialog.load()) << dialog.message().toStdString();
  ASSERT_EQ(dialog.piece()->count(), 2);
  EXPECT_EQ(dialog.piece()->itemText(0), "FRONT");
  EXPECT_TRUE(dialog.message().contains("4 notches")) << dialog.message().toStdString();
  EXPECT_TRUE(dialog.message().contains("grain 30.0°")) << dialog.message().toStdString();
  dialog.position()->setText("10 cm, 0");
  dialog.rotation()->setText("90");
  ASSERT_TRUE(dialog.importPiece()) << dialog.message().toStdString();

  const auto* pattern = std::get_if<PatternOutline>(&doc->scene().fabric.outline);
  ASSERT_NE(pattern, nullptr);
  EXPECT_EQ(pattern->piece, "FRONT");
  // Notch 1 at (10, 0) cm turned by 90° and moved 10 cm along x: (10, 10) cm.
  EXPECT_NEAR(pattern->shape.notches[0][0], 0.10, 1e-12);
  EXPECT_NEAR(pattern->shape.notches[0][1], 0.10, 1e-12);
  // The warp follows the piece's grain line, 30° turned by 90°.
  EXPECT_TRUE(doc->scene().material.angle_from_grain);
  EXPECT_NEAR(doc->scene().material.angle_deg, 120.0, 1e-6);
  // An angle typed in the material editor replaces the grain's, and stays.
  QLineEdit* angle = window.properties()->material()->angle()->edit();
  angle->setText("45 deg");
  emit angle->editingFinished();
  EXPECT_FALSE(doc->scene().material.angle_from_grain);
  EXPECT_NEAR(doc->scene().material.angle_deg, 45.0, 1e-9);
  EXPECT_NEAR(doc->parse(doc->json()).material.angle_deg, 45.0, 1e-9);
  doc->undoStack()->undo();
  EXPECT_TRUE(doc->scene().material.angle_from_grain);
  // The drawn panel less its 5 × 4 cm cut-out, meshed.
  ASSERT_NE(doc->model(), nullptr) << doc->modelProblem().toStdString();
  EXPECT_NEAR(MeshArea(*doc->model()) / ((40 * 30 + 40 + -20) * 1e-4), 1.0, 1e-3);

  // The grippers' editor lists the piece's marks, and holds by one: notch
  // 2, at (40, 15) cm of the piece, placed turned by 90° and moved by
  // (10 cm, 0): at (−5 cm, 40 cm), where a node of the mesh now sits.
  HoldsPanel* grippers = window.grippers();
  EXPECT_EQ(grippers->rule()->marks()->text().toStdString(),
            "FRONT: 4 notches, 2 drill holes, 1 internal line");
  grippers->rule()->mark()->setValue(2);
  ASSERT_TRUE(grippers->add("notch", 0)) << grippers->message().toStdString();
  const Gripper& held = doc->scene().grippers.back();
  EXPECT_EQ(held.select, (Selection{PatternMarkSelection{PatternMark::kNotch, 2}, std::nullopt}));
  ASSERT_EQ(doc->model()->grippers.back().nodes.size(), 1u);
  const int node = doc->model()->grippers.back().nodes[0];
  EXPECT_LT(
      (doc->model()->mesh.positions.row(node).head<2>() - Eigen::RowVector2d(-0.05, 0.40)).norm(),
      1e-9);
  doc->undoStack()->undo();

  // The view draws the piece's grain line on the fabric; the block it
  // replaced had none.
  QApplication::processEvents();
  ASSERT_NE(window.view()->renderer(), nullptr);
  EXPECT_TRUE(window.view()->renderer()->HasGrainLine());

  doc->undoStack()->undo();
  EXPECT_EQ(doc->scene(), before);
  QApplication::processEvents();
  ASSERT_NE(window.view()->renderer(), nullptr);
  EXPECT_FALSE(window.view()->renderer()->HasGrainLine());

  // A file that is not a pattern says so, and lists nothing.
  dialog.file()->setText(QString::fromStdString((dir / "missing.dxf").string()));
  EXPECT_FALSE(dialog.load());
  EXPECT_TRUE(dialog.message().contains("cannot be opened")) << dialog.message().toStdString();
  EXPECT_EQ(dialog.piece()->count(), 0);
}

}  // namespace
}  // namespace drape
