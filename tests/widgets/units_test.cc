// The workbench in the user's units: the property panel, the material
// dialog's moment–curvature plot and the units menu, for SI, textile and
// imperial. Numbers are checked against factors written out here (1 cm =
// 0.01 m, 1 in = 0.0254 m, 1 gf = 9.80665e-3 N, 1 oz = 0.27801385 N,
// 1 oz/in² = 430.9223 Pa). Runs under xvfb-run -a.
#include <gtest/gtest.h>

#include <QAction>
#include <QChart>
#include <QLineEdit>
#include <QMenu>
#include <QScatterSeries>
#include <QSettings>
#include <QSignalSpy>
#include <QValueAxis>
#include <QXYSeries>

#include <string>

#include "core/solve/step_state.h"
#include "support/test_paths.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/unit_settings.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

constexpr double kGf = 9.80665e-3, kOzf = 0.27801385, kIn = 0.0254;
constexpr double kOzPerIn2 = 430.9223;

QString StripFold() {
  return QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
}

// A field's text typed in as a user does: focus lost commits it.
void Type(QLineEdit* edit, const QString& text) {
  edit->setText(text);
  emit edit->editingFinished();
}

std::string Text(QLineEdit* edit) {
  return edit->text().toStdString();
}

// The strip fold is 20 × 2 cm, h = 0.0469 cm, w = 4.019e-3 oz/in²,
// E = 4196 oz/in² (resources/scenes/strip-fold.json).
TEST_F(Widgets, PropertyPanelShowsTheStripFoldInEachSystem) {
  SceneDocument doc;
  doc.open(StripFold());
  PropertyPanel panel(&doc);
  EXPECT_EQ(panel.unitSystem(), UnitSystem::kSI);
  EXPECT_EQ(Text(panel.outlineExtent()), "0.2 m, 0.02 m");
  EXPECT_EQ(Text(panel.thickness()->edit()), "0.000469 m");
  EXPECT_EQ(Text(panel.modulus()->edit()), "1.80815e+06 Pa");

  panel.setUnitSystem(UnitSystem::kTextile);
  EXPECT_EQ(Text(panel.outlineExtent()), "20 cm, 2 cm");
  EXPECT_EQ(Text(panel.thickness()->edit()), "0.469 mm");
  // 4.019e-3 × 430.9223 Pa / 9.80665e-3 N per g: 176.602 g/m² of fabric.
  EXPECT_EQ(Text(panel.weight()->edit()), "176.602 g/m²");
  // 4196 × 430.9223 / 98.0665 Pa per gf/cm².
  EXPECT_EQ(Text(panel.modulus()->edit()), "18438 gf/cm²");
  EXPECT_NE(panel.modulus()->edit()->toolTip().toStdString().find("gf/cm²"), std::string::npos);

  panel.setUnitSystem(UnitSystem::kImperial);
  EXPECT_EQ(Text(panel.outlineExtent()), "7.87402 in, 0.787402 in");  // 0.2 m / 0.0254
  EXPECT_EQ(Text(panel.thickness()->edit()), "0.0184646 in");
  EXPECT_EQ(Text(panel.weight()->edit()), "0.004019 oz/in²");  // as the scene says
  EXPECT_EQ(Text(panel.modulus()->edit()), "4196 oz/in²");
}

// Any unit the scene reader takes, in any system: the scene gets SI.
TEST_F(Widgets, PropertyFieldsAcceptAnyUnit) {
  SceneDocument doc;
  doc.open(StripFold());
  PropertyPanel panel(&doc);
  panel.setUnitSystem(UnitSystem::kTextile);
  Type(panel.thickness()->edit(), "3 in");
  EXPECT_NEAR(doc.scene().material.thickness, 3 * kIn, 1e-15);  // 0.0762 m
  EXPECT_EQ(Text(panel.thickness()->edit()), "3 in");           // the user's own text stays
  Type(panel.weight()->edit(), "180 g/m^2");                    // a mass per area, weighed
  EXPECT_NEAR(doc.scene().material.areal_weight, 180 * kGf, 1e-12);
  Type(panel.modulus()->edit(), "2000 oz/in^2");
  const auto& iso = std::get<IsotropicMembrane>(doc.scene().material.membrane);
  EXPECT_NEAR(iso.youngs_modulus, 2000 * kOzPerIn2, 1e-7 * 2000 * kOzPerIn2);  // 7 digits given
  // Another system shows the typed values anew in its own units.
  panel.setUnitSystem(UnitSystem::kSI);
  EXPECT_EQ(Text(panel.thickness()->edit()), "0.0762 m");
  EXPECT_EQ(Text(panel.weight()->edit()), "1.7652 N/m²");
  // A length typed into the outline in inches is read as the reader reads it.
  EXPECT_TRUE(panel.setOutline("rectangle", "10 in, 1 in"));
  const auto& r = std::get<RectangleOutline>(doc.scene().fabric.outline);
  EXPECT_NEAR(r.size[0], 10 * kIn, 1e-15);
  EXPECT_EQ(Text(panel.outlineExtent()), "0.254 m, 0.0254 m");
}

struct PlotPoints {
  QString x_title, y_title;
  QList<QPointF> measured;
};

PlotPoints Plotted(MaterialDialog& dialog) {
  PlotPoints p;
  p.x_title = dialog.chart()->axes(Qt::Horizontal).value(0)->titleText();
  p.y_title = dialog.chart()->axes(Qt::Vertical).value(0)->titleText();
  for (QAbstractSeries* s : dialog.chart()->series())
    if (auto* scatter = qobject_cast<QScatterSeries*>(s)) p.measured = scatter->points();
  return p;
}

// The moment–curvature plot: axis titles name the system's units and each
// measured point is its SI value over the unit's factor.
TEST_F(Widgets, MaterialPlotIsDrawnInEachSystem) {
  SceneDocument doc;
  doc.open(StripFold());
  MaterialDialog dialog(&doc);
  dialog.file()->setText(QString::fromStdString(
      (test::SourceDir() / "resources/materials/kawabata/cotton-twill-warp.csv").string()));
  ASSERT_TRUE(dialog.preview()) << dialog.message().toStdString();
  const PlotPoints si = Plotted(dialog);
  EXPECT_EQ(si.x_title.toStdString(), "curvature K [1/m]");
  EXPECT_EQ(si.y_title.toStdString(), "moment M [N·m/m]");
  ASSERT_EQ(si.measured.size(), 51);
  // The data run from −2.5 to 2.5 1/cm: 250 1/m.
  EXPECT_NEAR(si.measured.back().x(), 250, 1e-9);
  EXPECT_NE(dialog.message().toStdString().find("to 250 1/m"), std::string::npos)
      << dialog.message().toStdString();

  const struct {
    UnitSystem system;
    const char *x_title, *y_title;
    double curvature_factor, moment_factor;  // SI per unit
  } cases[] = {
      {UnitSystem::kTextile, "curvature K [1/cm]", "moment M [gf·cm/cm]", 100, kGf},
      {UnitSystem::kImperial, "curvature K [1/in]", "moment M [oz·in/in]", 1 / kIn, kOzf},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(ToString(c.system));
    dialog.setUnitSystem(c.system);
    const PlotPoints p = Plotted(dialog);
    EXPECT_EQ(p.x_title.toStdString(), c.x_title);
    EXPECT_EQ(p.y_title.toStdString(), c.y_title);
    ASSERT_EQ(p.measured.size(), si.measured.size());
    for (int i = 0; i < p.measured.size(); ++i) {
      EXPECT_NEAR(p.measured[i].x(), si.measured[i].x() / c.curvature_factor, 1e-9);
      EXPECT_NEAR(p.measured[i].y(),
                  si.measured[i].y() / c.moment_factor,
                  1e-6 * std::abs(si.measured[i].y() / c.moment_factor) + 1e-12);
    }
  }
  // In textile units the points are the KES file's own numbers: 2.5 1/cm.
  dialog.setUnitSystem(UnitSystem::kTextile);
  EXPECT_NEAR(Plotted(dialog).measured.back().x(), 2.5, 1e-12);
  EXPECT_NE(dialog.message().toStdString().find("to 2.5 1/cm"), std::string::npos)
      << dialog.message().toStdString();
}

// The menu's choice is kept across sessions; "Scene's own" follows the
// scene's units as written (the strip fold: cm, so textile).
TEST_F(Widgets, UnitSettingsFollowTheMenuAndTheScene) {
  QSettings().remove("units");
  SceneDocument doc;
  doc.open(StripFold());
  UnitSettings units;
  EXPECT_FALSE(units.choice().has_value());
  QSignalSpy spy(&units, &UnitSettings::changed);
  units.followScene(&doc);
  EXPECT_EQ(units.system(), UnitSystem::kTextile);
  ASSERT_EQ(spy.count(), 1);
  EXPECT_EQ(spy.takeFirst().at(0).value<UnitSystem>(), UnitSystem::kTextile);

  QMenu* menu = units.menu();
  ASSERT_EQ(menu->actions().size(), 4);
  QAction* imperial = nullptr;
  for (QAction* a : menu->actions())
    if (a->data().toString() == "imperial") imperial = a;
  ASSERT_NE(imperial, nullptr);
  imperial->trigger();
  EXPECT_EQ(units.system(), UnitSystem::kImperial);
  EXPECT_TRUE(imperial->isChecked());
  EXPECT_EQ(spy.count(), 1);
  EXPECT_EQ(QSettings().value("units").toString().toStdString(), "imperial");
  // A new session starts with the saved choice; the scene does not override it.
  UnitSettings next;
  next.followScene(&doc);
  EXPECT_EQ(next.system(), UnitSystem::kImperial);
  // Wired to the panel: the panel follows the menu.
  PropertyPanel panel(&doc);
  QObject::connect(&next, &UnitSettings::changed, &panel, &PropertyPanel::setUnitSystem);
  next.setChoice(UnitSystem::kTextile);
  EXPECT_EQ(Text(panel.outlineExtent()), "20 cm, 2 cm");
  next.setChoice(std::nullopt);
  EXPECT_EQ(next.system(), UnitSystem::kTextile);
  delete menu;
  QSettings().remove("units");
}

// The run dock's plots: a probe 2 cm up and a gripper carrying 0.5 N,
// shown in each system's unit, the axis naming it.
TEST_F(Widgets, RunPlotsShowHeightsAndReactionsInEachSystem) {
  StepState step;
  step.stage = 0;
  step.step = 1;
  step.probes = {{"end", {0, 0, 0.02}}};
  step.reactions = {{"end", {0.3, 0, 0.4}}};  // |F| = 0.5 N
  ProbePlot probes;
  ReactionPlot reactions;
  probes.add(step);
  reactions.add(step);
  const struct {
    UnitSystem system;
    const char *height_title, *force_title;
    double height, force;
  } cases[] = {{UnitSystem::kSI, "z [m]", "reaction [N]", 0.02, 0.5},
               {UnitSystem::kTextile, "z [cm]", "reaction [gf]", 2, 0.5 / kGf},
               {UnitSystem::kImperial, "z [in]", "reaction [oz]", 0.02 / kIn, 0.5 / kOzf}};
  for (const auto& c : cases) {
    SCOPED_TRACE(ToString(c.system));
    probes.setUnitSystem(c.system);
    reactions.setUnitSystem(c.system);
    EXPECT_EQ(probes.heightAxis()->titleText().toStdString(), c.height_title);
    EXPECT_EQ(reactions.forceAxis()->titleText().toStdString(), c.force_title);
    const auto* series = qobject_cast<QXYSeries*>(probes.chart()->series().value(0));
    ASSERT_NE(series, nullptr);
    EXPECT_NEAR(series->at(0).y(), c.height, 1e-12 * c.height);
    EXPECT_NEAR(reactions.value(0, 0), c.force, 1e-8 * c.force);  // 0.27801385: 8 digits
    EXPECT_DOUBLE_EQ(probes.lastHeight(0), 0.02);                 // SI, whatever is shown
    EXPECT_DOUBLE_EQ(reactions.force(0, 0).z(), 0.4);
  }
  // A step added later is shown in the unit in effect.
  step.step = 2;
  step.reactions[0].value = {0, 0, kOzf};
  reactions.add(step);
  EXPECT_NEAR(reactions.value(0, 1), 1.0, 1e-8);  // 1 oz
}

}  // namespace
}  // namespace drape
