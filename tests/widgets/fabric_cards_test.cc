// The material dialog in a textile engineer's terms: the library as cards
// giving each fabric's B, G, weight and thickness in KES units — the cotton
// twill's B the paper's polynomial's mean slope between 0.5 and 1.5 1/cm,
// Σ cₖ(1.5ᵏ − 0.5ᵏ) = 0.4875 gf·cm²/cm — and a fabric entered from a lab
// summary, which becomes the scene's material as one undoable edit, its SI
// values worked out from the units by hand.
#include <gtest/gtest.h>

#include <QListWidget>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <numbers>
#include <variant>

#include "support/fabric_summaries.h"
#include "ui/widgets/fabric_cards.h"
#include "ui/widgets/fabric_summary_form.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_templates.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

TEST_F(Widgets, LibraryCardsAndALabSummaryInTextileTerms) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.newFromTemplate(BlankTemplate().file));
  MaterialDialog dialog(window.document(), &window);
  dialog.show();

  FabricCards* cards = dialog.library();
  ASSERT_GE(cards->count(), 4);
  ASSERT_TRUE(dialog.chooseLibrary("cotton-twill"));
  const double c[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  double b = 0;
  for (int k = 1; k <= 5; ++k) b += c[k - 1] * (std::pow(1.5, k) - std::pow(0.5, k));
  const QString card = cards->currentItem()->text();
  EXPECT_TRUE(card.contains(QString("B %1 gf·cm²/cm").arg(b, 0, 'g', 3))) << card.toStdString();
  // 0.02665 gf/cm² is 266.5 g/m²; h = 0.0489 cm.
  EXPECT_TRUE(card.contains("266 g/m²") || card.contains("267 g/m²")) << card.toStdString();
  EXPECT_TRUE(card.contains("0.489 mm")) << card.toStdString();

  // A shirting from its summary (support/fabric_summaries.h).
  FabricSummaryForm* form = dialog.labSummary();
  FabricSummary s = test::Shirting();
  form->setSummary(s);
  const Scene before = window.document()->scene();
  ASSERT_TRUE(form->apply()) << form->message().toStdString();
  const Material& m = window.document()->scene().material;
  EXPECT_DOUBLE_EQ(m.thickness, 0.5e-3);
  EXPECT_NEAR(m.areal_weight, 0.150 * 9.80665, 1e-12);
  const auto& o = std::get<OrthotropicMembrane>(m.membrane);
  EXPECT_NEAR(o.e1, 400 * 0.980665 / 0.5e-3, 1e-6);
  EXPECT_NEAR(o.g12, 0.8 * 0.980665 / (0.5e-3 * std::numbers::pi / 180), 1e-6);
  EXPECT_NEAR(*std::get<LinearBending>(m.bending.warp).rigidity, 0.08 * 9.80665e-5, 1e-18);
  window.document()->undoStack()->undo();
  EXPECT_EQ(window.document()->scene(), before);
  // Zero where a fabric has a value: said, nothing changed.
  s.shear = 0;
  form->setSummary(s);
  EXPECT_FALSE(form->apply());
  EXPECT_EQ(form->message().toStdString(),
            "the shear rigidity G must be greater than zero, found 0");
  EXPECT_EQ(window.document()->scene(), before);
}

}  // namespace
}  // namespace drape
