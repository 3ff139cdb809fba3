// The unit system wired through the workbench's window: the Units menu in
// the menu bar, the scene's own system guessed as a file opens, and every
// panel, plot, the colour bar and the material dialog following the menu;
// drape-studio --units for scripts. Runs under xvfb-run -a.
#include <gtest/gtest.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include <QAction>
#include <QChart>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTest>
#include <QValueAxis>

#include <cstdio>
#include <filesystem>
#include <string>

#include "support/test_paths.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/unit_settings.h"
#include "ui/widgets/view_controller.h"
#include "ui/widgets/workbench_actions.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

QString Scene(const char* name) {
  return QString::fromStdString((test::ScenesDir() / name).string());
}

std::string Text(QLineEdit* edit) {
  return edit->text().toStdString();
}

// The colour bar's title in the view ("" when no bar is drawn).
std::string BarTitle(MainWindow& window) {
  vtkPropCollection* props = window.view()->renderer()->renderer()->GetViewProps();
  props->InitTraversal();
  while (vtkProp* p = props->GetNextProp())
    if (auto* bar = vtkScalarBarActor::SafeDownCast(p))
      return bar->GetVisibility() && bar->GetTitle() ? bar->GetTitle() : "";
  return "";
}

// The menu bar's Units ▸ item whose data is `name` ("si", …, "scene").
QAction* UnitsItem(MainWindow& window, const QString& name) {
  for (QAction* top : window.menuBar()->actions()) {
    if (!top->menu() || top->menu()->title() != "&Units") continue;
    for (QAction* a : top->menu()->actions())
      if (a->data().toString() == name) return a;
  }
  return nullptr;
}

class WindowUnits : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    QSettings().remove("units");  // the scene's own
    window_ = std::make_unique<MainWindow>();
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override {
    window_.reset();
    QSettings().remove("units");
  }
  std::unique_ptr<MainWindow> window_;
};

// The strip fold is written in cm (20 × 2 cm, h = 0.0469 cm): opened with
// "Scene's own" it shows in textile units; Units ▸ Imperial then turns the
// panel, the run dock's axes and the colour bar to inches.
TEST_F(WindowUnits, TheMenuTurnsThePanelsAndTheColourBar) {
  MainWindow& w = *window_;
  ASSERT_TRUE(w.openScene(Scene("strip-fold.json")));
  EXPECT_EQ(w.units()->system(), UnitSystem::kTextile);
  ASSERT_NE(UnitsItem(w, "scene"), nullptr) << "no Units menu in the menu bar";
  EXPECT_TRUE(UnitsItem(w, "scene")->isChecked());
  EXPECT_EQ(Text(w.properties()->outlineExtent()), "20 cm, 2 cm");
  EXPECT_EQ(Text(w.properties()->thickness()->edit()), "0.469 mm");
  EXPECT_EQ(Text(w.properties()->modulus()->edit()), "18438 gf/cm²");
  EXPECT_EQ(w.probePlot()->heightAxis()->titleText().toStdString(), "z [cm]");
  EXPECT_EQ(w.reactionPlot()->forceAxis()->titleText().toStdString(), "reaction [gf]");
  EXPECT_EQ(BarTitle(w), "") << "no field chosen: no bar";
  ASSERT_TRUE(w.setField("curvature"));
  EXPECT_EQ(BarTitle(w), "curvature [1/cm]");
  EXPECT_EQ(w.view()->unitSystem(), UnitSystem::kTextile);

  UnitsItem(w, "imperial")->trigger();
  EXPECT_EQ(w.units()->system(), UnitSystem::kImperial);
  EXPECT_EQ(Text(w.properties()->outlineExtent()), "7.87402 in, 0.787402 in");  // 0.2 m / 0.0254
  EXPECT_EQ(Text(w.properties()->thickness()->edit()), "0.0184646 in");
  EXPECT_EQ(Text(w.properties()->modulus()->edit()), "4196 oz/in²");  // as the paper gives it
  EXPECT_EQ(w.probePlot()->heightAxis()->titleText().toStdString(), "z [in]");
  EXPECT_EQ(w.reactionPlot()->forceAxis()->titleText().toStdString(), "reaction [oz]");
  EXPECT_EQ(BarTitle(w), "curvature [1/in]");
  // The choice holds over the next scene opened, and is kept for the next session.
  ASSERT_TRUE(w.openScene(Scene("diagonal-fold.json")));
  EXPECT_EQ(BarTitle(w), "curvature [1/in]");
  EXPECT_EQ(QSettings().value("units").toString().toStdString(), "imperial");
  UnitsItem(w, "si")->trigger();
  EXPECT_EQ(BarTitle(w), "curvature [1/m]");
  EXPECT_EQ(Text(w.properties()->thickness()->edit()), "0.000489 m");
}

// "Scene's own" is guessed again from each file opened: the block drape is
// written in inches, the strip fold in cm.
TEST_F(WindowUnits, TheScenesOwnSystemIsGuessedAsEachFileOpens) {
  MainWindow& w = *window_;
  ASSERT_TRUE(w.openScene(Scene("block-drape.json")));
  EXPECT_EQ(w.units()->system(), UnitSystem::kImperial);
  EXPECT_EQ(w.properties()->unitSystem(), UnitSystem::kImperial);
  EXPECT_EQ(Text(w.properties()->thickness()->edit()), "0.02135 in");
  ASSERT_TRUE(w.openScene(Scene("strip-fold.json")));
  EXPECT_EQ(w.units()->system(), UnitSystem::kTextile);
  EXPECT_EQ(Text(w.properties()->outlineExtent()), "20 cm, 2 cm");
  // A template is its file's units too.
  ASSERT_TRUE(w.newFromTemplate(Scene("block-drape.json")));
  EXPECT_EQ(w.properties()->unitSystem(), UnitSystem::kImperial);
}

// The material dialog opened from the window draws in the window's system
// and follows the menu while it is open.
TEST_F(WindowUnits, TheMaterialDialogDrawsInTheChosenSystem) {
  MainWindow& w = *window_;
  ASSERT_TRUE(w.openScene(Scene("strip-fold.json")));
  UnitsItem(w, "imperial")->trigger();
  ASSERT_TRUE(w.actions()->material()->isEnabled());
  w.actions()->material()->trigger();
  auto* dialog = w.findChild<MaterialDialog*>();
  ASSERT_NE(dialog, nullptr);
  EXPECT_EQ(dialog->unitSystem(), UnitSystem::kImperial);
  dialog->file()->setText(QString::fromStdString(
      (test::SourceDir() / "resources/materials/kawabata/cotton-twill-warp.csv").string()));
  ASSERT_TRUE(dialog->preview()) << dialog->message().toStdString();
  auto axis_title = [&](Qt::Orientation o) {
    return dialog->chart()->axes(o).value(0)->titleText().toStdString();
  };
  EXPECT_EQ(axis_title(Qt::Horizontal), "curvature K [1/in]");
  EXPECT_EQ(axis_title(Qt::Vertical), "moment M [oz·in/in]");
  // The data end at 2.5 1/cm = 6.35 1/in.
  auto* x = qobject_cast<QValueAxis*>(dialog->chart()->axes(Qt::Horizontal).value(0));
  ASSERT_NE(x, nullptr);
  EXPECT_NEAR(x->max(), 6.35, 0.35) << "the axis reaches the data's end";
  UnitsItem(w, "textile")->trigger();
  EXPECT_EQ(dialog->unitSystem(), UnitSystem::kTextile);
  EXPECT_EQ(axis_title(Qt::Horizontal), "curvature K [1/cm]");
  EXPECT_EQ(axis_title(Qt::Vertical), "moment M [gf·cm/cm]");
  dialog->close();
}

// drape-studio --units: the session's system, not saved; a wrong name is
// refused before the window opens.
TEST_F(WindowUnits, StudioTakesTheUnitsOnItsCommandLine) {
  auto studio = [](const std::string& args, std::string* out) {
    const std::string command = std::string(test::DrapeStudio()) + " " + args + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    char buf[512];
    while (fgets(buf, sizeof buf, pipe)) *out += buf;
    return pclose(pipe);
  };
  std::string out;
  EXPECT_NE(studio("--units furlongs --quit", &out), 0);
  EXPECT_NE(out.find("--units furlongs: one of si, textile, imperial, scene"), std::string::npos)
      << out;
  // In the window: the session's choice; the menu shows it, nothing saved.
  window_->units()->useChoice(UnitSystem::kImperial);
  ASSERT_TRUE(window_->openScene(Scene("strip-fold.json")));
  EXPECT_EQ(Text(window_->properties()->outlineExtent()), "7.87402 in, 0.787402 in");
  EXPECT_TRUE(UnitsItem(*window_, "imperial")->isChecked());
  EXPECT_FALSE(QSettings().contains("units"));

  const std::string shot = (std::filesystem::temp_directory_path() /
                            ("drape-studio-units-" + std::to_string(getpid()) + ".png"))
                               .string();
  out.clear();
  const int status = studio("'" + Scene("strip-fold.json").toStdString() +
                                "' --units textile --window-screenshot '" + shot + "' --quit",
                            &out);
  EXPECT_EQ(status, 0) << out;
  EXPECT_TRUE(std::filesystem::exists(shot)) << out;
  std::filesystem::remove(shot);
}

}  // namespace
}  // namespace drape
