// The editors the Units menu turns besides the property panel: the
// supports' and grippers' selections, the probes' positions, the scene
// tree's summaries and the contact penalty, each shown in the system
// chosen and each taking any unit typed. Runs under xvfb-run -a.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "support/test_paths.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/selection_rule.h"
#include "ui/widgets/unit_settings.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

QString Scene(const char* name) {
  return QString::fromStdString((test::ScenesDir() / name).string());
}

std::string Row(QListWidget* list, int row) {
  return list->item(row)->text().toStdString();
}

std::string Summary(ModelTree* tree, ModelTree::Part part, int index = -1) {
  QTreeWidgetItem* item = tree->item(part, index);
  return item ? item->text(1).toStdString() : "(no item)";
}

QPushButton* Button(QWidget* panel, const QString& text) {
  for (QPushButton* b : panel->findChildren<QPushButton*>())
    if (b->text() == text) return b;
  return nullptr;
}

class EditorUnits : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    QSettings().remove("units");  // the scene's own
    window_ = std::make_unique<MainWindow>();
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
    // The diagonal fold is written in cm: it opens in textile units.
    ASSERT_TRUE(window_->openScene(Scene("diagonal-fold.json")));
    ASSERT_EQ(window_->units()->system(), UnitSystem::kTextile);
  }
  void TearDown() override {
    window_.reset();
    QSettings().remove("units");
  }
  std::unique_ptr<MainWindow> window_;
};

// The gripper 'corner' holds the point (-10 cm, -10 cm) and the support
// 'far_corner' (10 cm, 10 cm): the lists and the point field show them in
// the system chosen.
TEST_F(EditorUnits, HoldsShowTheirPointsInTheChosenSystem) {
  MainWindow& w = *window_;
  HoldsPanel* grippers = w.grippers();
  HoldsPanel* supports = w.supports();
  EXPECT_EQ(Row(grippers->list(), 0), "corner: point (-10 cm, -10 cm), pinned");
  EXPECT_EQ(Row(supports->list(), 0), "far_corner: point (10 cm, 10 cm), pinned");
  EXPECT_EQ(grippers->rule()->rule()->currentText().toStdString(), "point");
  EXPECT_EQ(grippers->rule()->point()->text().toStdString(), "-10 cm, -10 cm");

  w.units()->useChoice(UnitSystem::kImperial);
  EXPECT_EQ(Row(grippers->list(), 0), "corner: point (-3.93701 in, -3.93701 in), pinned");
  EXPECT_EQ(grippers->rule()->point()->text().toStdString(), "-3.93701 in, -3.93701 in");
  EXPECT_EQ(Row(supports->list(), 0), "far_corner: point (3.93701 in, 3.93701 in), pinned");

  w.units()->useChoice(UnitSystem::kSI);
  EXPECT_EQ(Row(grippers->list(), 0), "corner: point (-0.1 m, -0.1 m), pinned");
  EXPECT_EQ(grippers->rule()->point()->text().toStdString(), "-0.1 m, -0.1 m");

  // Selections of other shapes: a line's ends, a box's corners.
  EXPECT_EQ(DescribeSelection(Selection{LineSelection{{0, 0}, {0.2, 0}}, std::nullopt},
                              UnitSystem::kTextile)
                .toStdString(),
            "line (0, 0) to (20 cm, 0)");
  EXPECT_EQ(DescribeSelection(Selection{BoxSelection{{-0.0254, 0}, {0.0508, 0.0254}}, std::nullopt},
                              UnitSystem::kImperial)
                .toStdString(),
            "box (-1 in, 0) to (2 in, 1 in)");
}

// The point field takes any unit the scene reader does, whatever the
// system shown: "2 in, 0" in a textile panel holds the node nearest
// (0.0508 m, 0), and the list then says so in cm.
TEST_F(EditorUnits, APointTypedInAnyUnitIsStoredInSI) {
  MainWindow& w = *window_;
  HoldsPanel* supports = w.supports();
  supports->rule()->rule()->setCurrentText("point");
  supports->rule()->point()->setText("2 in, 0");
  QPushButton* add = Button(supports, "Add support");
  ASSERT_NE(add, nullptr);
  add->click();
  const auto& held = w.document()->scene().supports;
  ASSERT_EQ(held.size(), 2u) << supports->message().toStdString();
  const auto* at = std::get_if<PointSelection>(&held.back().select.shape);
  ASSERT_NE(at, nullptr);
  EXPECT_NEAR(at->at[0], 0.0508, 1e-12);
  EXPECT_EQ(at->at[1], 0.0);
  EXPECT_EQ(Row(supports->list(), 1), held.back().name + ": point (5.08 cm, 0), pinned");
  EXPECT_EQ(supports->rule()->point()->text().toStdString(), "5.08 cm, 0");

  // Text that is no length is refused with the reader's reason; nothing added.
  supports->rule()->point()->setText("2 gf, 0");
  add->click();
  EXPECT_EQ(w.document()->scene().supports.size(), 2u);
  EXPECT_NE(supports->message().toStdString().find("point:"), std::string::npos)
      << supports->message().toStdString();
}

// A drape tester's disc: every node within the typed radius of the typed
// centre, stored in SI, listed in the shown unit, shown again when picked.
TEST_F(EditorUnits, ACircleHoldsEveryNodeWithinItsRadius) {
  MainWindow& w = *window_;
  HoldsPanel* supports = w.supports();
  supports->rule()->rule()->setCurrentText("circle");
  supports->rule()->point()->setText("1 in, 0");
  supports->rule()->radius()->setText("30 mm");
  QPushButton* add = Button(supports, "Add support");
  ASSERT_NE(add, nullptr);
  add->click();
  const auto& held = w.document()->scene().supports;
  ASSERT_EQ(held.size(), 2u) << supports->message().toStdString();
  const auto* disc = std::get_if<CircleSelection>(&held.back().select.shape);
  ASSERT_NE(disc, nullptr);
  EXPECT_NEAR(disc->center[0], 0.0254, 1e-12);
  EXPECT_EQ(disc->center[1], 0.0);
  EXPECT_NEAR(disc->radius, 0.03, 1e-12);
  EXPECT_EQ(Row(supports->list(), 1),
            held.back().name + ": circle (2.54 cm, 0), radius 3 cm, pinned");

  // Picking another row and this one again shows the circle's rows.
  supports->list()->setCurrentRow(0);
  supports->list()->setCurrentRow(1);
  EXPECT_EQ(supports->rule()->rule()->currentText().toStdString(), "circle");
  EXPECT_EQ(supports->rule()->radius()->text().toStdString(), "3 cm");

  // A radius that is no length, or not positive, is refused; nothing added.
  for (const char* bad : {"2 gf", "0 cm", "-1 cm"}) {
    supports->rule()->radius()->setText(bad);
    add->click();
    EXPECT_EQ(w.document()->scene().supports.size(), 2u) << bad;
    EXPECT_NE(supports->message().toStdString().find("radius:"), std::string::npos)
        << supports->message().toStdString();
  }
}

// The probe 'corner' at (-10 cm, -10 cm) and one added by typing inches.
TEST_F(EditorUnits, ProbesShowTheirPositionsInTheChosenSystem) {
  MainWindow& w = *window_;
  ProbesPanel* probes = w.probes();
  EXPECT_EQ(Row(probes->list(), 0), "corner at (-10 cm, -10 cm)");
  EXPECT_EQ(Row(probes->list(), 1), "centre at (0, 0)");
  w.units()->useChoice(UnitSystem::kImperial);
  EXPECT_EQ(Row(probes->list(), 0), "corner at (-3.93701 in, -3.93701 in)");
  w.units()->useChoice(UnitSystem::kSI);
  EXPECT_EQ(Row(probes->list(), 0), "corner at (-0.1 m, -0.1 m)");

  w.units()->useChoice(UnitSystem::kTextile);
  probes->at()->setText("2 in, 0");
  QPushButton* add = Button(probes, "Add");
  ASSERT_NE(add, nullptr);
  add->click();
  const auto& all = w.document()->scene().probes;
  ASSERT_EQ(all.size(), 3u) << probes->message().toStdString();
  EXPECT_NEAR(all.back().at[0], 0.0508, 1e-12);
  EXPECT_EQ(all.back().at[1], 0.0);
  EXPECT_EQ(Row(probes->list(), 2), all.back().name + " at (5.08 cm, 0)");
  // Coordinates being typed turn with the menu.
  w.units()->useChoice(UnitSystem::kImperial);
  EXPECT_EQ(probes->at()->text().toStdString(), "2 in, 0");
}

// The scene tree's one-line summaries: the 20 × 20 cm square, h = 0.0489
// cm and w = 0.02665 gf/cm² (266.5 g/m²), the holds' points, the probes'.
TEST_F(EditorUnits, TheTreeSummariesFollowTheChosenSystem) {
  MainWindow& w = *window_;
  ModelTree* tree = w.tree();
  using P = ModelTree::Part;
  EXPECT_EQ(Summary(tree, P::kFabric), "rectangle 20 × 20 cm");
  EXPECT_EQ(Summary(tree, P::kMaterial), "h = 0.489 mm, w = 266.5 g/m²");
  EXPECT_EQ(Summary(tree, P::kGrippers, 0), "point (-10 cm, -10 cm), position");
  EXPECT_EQ(Summary(tree, P::kSupports, 0), "point (10 cm, 10 cm), position");
  EXPECT_EQ(Summary(tree, P::kProbes, 0), "(-10 cm, -10 cm)");

  w.units()->useChoice(UnitSystem::kImperial);
  EXPECT_EQ(Summary(tree, P::kFabric), "rectangle 7.874 × 7.874 in");
  EXPECT_EQ(Summary(tree, P::kMaterial), "h = 0.01925 in, w = 0.006065 oz/in²");
  EXPECT_EQ(Summary(tree, P::kGrippers, 0), "point (-3.93701 in, -3.93701 in), position");

  w.units()->useChoice(UnitSystem::kSI);
  EXPECT_EQ(Summary(tree, P::kFabric), "rectangle 0.2 × 0.2 m");
  EXPECT_EQ(Summary(tree, P::kMaterial), "h = 0.000489 m, w = 2.613 N/m²");
  EXPECT_EQ(Summary(tree, P::kProbes, 0), "(-0.1 m, -0.1 m)");
}

// The contact penalty in the system's unit, read back to the same value;
// the obstacle's JSON stays as the scene file writes it.
TEST_F(EditorUnits, TheContactPenaltyFollowsTheChosenSystem) {
  MainWindow& w = *window_;
  ObstaclesPanel* obstacles = w.obstacles();
  EXPECT_EQ(obstacles->penalty()->text().toStdString(), "auto");
  ASSERT_TRUE(obstacles->setContact("2e8 N/m^3", "0")) << obstacles->message().toStdString();
  EXPECT_EQ(obstacles->penalty()->text().toStdString(), "20394.3 gf/cm³");
  w.units()->useChoice(UnitSystem::kImperial);
  EXPECT_EQ(obstacles->penalty()->text().toStdString(), "11788.7 oz/in³");
  // What the field shows reads back (to its six digits).
  ASSERT_TRUE(obstacles->setContact(obstacles->penalty()->text(), "0"))
      << obstacles->message().toStdString();
  EXPECT_NEAR(*w.document()->scene().contact->penalty, 2e8, 2e8 * 1e-5);
  w.units()->useChoice(UnitSystem::kSI);
  const std::string si = obstacles->penalty()->text().toStdString();
  EXPECT_TRUE(si.starts_with("2") && si.ends_with("e+08 N/m³")) << si;
}

// The table's plane at z = -0.02445 cm: its text gives the lengths in the
// system chosen (1 in = 2.54 cm), the label names the unit, and applying
// the text shown leaves the scene as it was.
TEST_F(EditorUnits, TheObstaclesLengthsFollowTheChosenSystem) {
  MainWindow& w = *window_;
  ObstaclesPanel* obstacles = w.obstacles();
  ASSERT_EQ(obstacles->list()->currentRow(), 0);
  auto point = [&] {
    const nlohmann::json o = nlohmann::json::parse(obstacles->text()->toPlainText().toStdString());
    return o["plane"]["point"];
  };
  EXPECT_EQ(point(), nlohmann::json::parse(R"([0, 0, "-0.02445 cm"])"));
  const double z = std::get<PlaneShape>(w.document()->scene().obstacles[0].shape).point[2];
  EXPECT_NEAR(z, -0.02445e-2, 1e-15);
  w.units()->useChoice(UnitSystem::kImperial);
  char inches[32];
  std::snprintf(inches, sizeof inches, "%.6g in", -0.02445 / 2.54);
  EXPECT_EQ(point(), nlohmann::json::parse("[0, 0, \"" + std::string(inches) + "\"]"));
  EXPECT_TRUE(Button(obstacles, "Apply") != nullptr);
  ASSERT_TRUE(obstacles->applyText(obstacles->text()->toPlainText()))
      << obstacles->message().toStdString();
  EXPECT_NEAR(std::get<PlaneShape>(w.document()->scene().obstacles[0].shape).point[2],
              z,
              1e-6 * std::abs(z));
  w.units()->useChoice(UnitSystem::kSI);
  EXPECT_NEAR(point()[2].get<double>(), z, 1e-6 * std::abs(z));
  bool named = false;
  for (QLabel* label : obstacles->findChildren<QLabel*>())
    named |= label->text().contains("lengths in m;");
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace drape
