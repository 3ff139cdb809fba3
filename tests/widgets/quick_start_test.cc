// The README's quick start, done in the workbench as it says, its pictures
// taken on the way: a template with the fabric over the dress form, a
// library fabric chosen, the form sized and the fabric laid on it, the run
// and its look, the export. Each step is checked (the scene holds what the
// step set, the run converges on a stable rest state, each picture shows
// the fabric). With DRAPE_QUICK_START_IMAGES set to a folder the pictures
// are written there (scripts/quick_start_images.sh: docs/images/quick-start),
// so the README's are the workbench's of today; without it, to a temporary
// folder, and the README's own are checked to be there, the same size.
#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QImage>
#include <QLineEdit>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstdlib>
#include <variant>

#include "support/test_paths.h"
#include "ui/widgets/form_editor.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/scene_document.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

constexpr double kFormHeight = 0.60;  // the dress form's neck, resources/forms/make_dress_form.py

class QuickStart : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    ASSERT_TRUE(temp_.isValid());
    const char* wanted = std::getenv("DRAPE_QUICK_START_IMAGES");
    out_ = QDir(wanted ? QString(wanted) : temp_.path());
    ASSERT_TRUE(out_.mkpath("."));
  }
  // Saves `picture` as `name`, checking that more than `least_fabric`
  // pixels show the fabric (none asked of a dialog: -1).
  void Keep(const QImage& picture, const char* name, int least_fabric) {
    ASSERT_FALSE(picture.isNull()) << name;
    if (least_fabric >= 0) EXPECT_GT(CountFabric(picture), least_fabric) << name;
    ASSERT_TRUE(picture.save(out_.filePath(name))) << name;
    names_.push_back(name);
  }

  QTemporaryDir temp_;
  QDir out_;
  std::vector<const char*> names_;
};

TEST_F(QuickStart, AsTheReadmeSays) {
  MainWindow window;
  window.resize(1440, 900);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));

  // 1. File ▸ New from template ▸ Fabric over the dress form.
  for (QAction* a : window.findChild<QMenu*>("file.templates")->actions())
    if (a->text() == "Fabric over the dress form") a->trigger();
  SceneDocument* doc = window.document();
  ASSERT_EQ(doc->scene().obstacles.size(), 1u);
  QTest::qWait(200);
  Keep(window.grab().toImage(), "1-template.png", 500);

  // 2. Edit ▸ Material… ▸ Library: the cotton twill.
  window.findChild<QAction*>("edit.material")->trigger();
  auto* dialog = window.findChild<MaterialDialog*>();
  ASSERT_NE(dialog, nullptr);
  ASSERT_TRUE(dialog->chooseLibrary("cotton-twill"));
  ASSERT_TRUE(dialog->applyLibrary()) << dialog->message().toStdString();
  EXPECT_DOUBLE_EQ(doc->scene().material.thickness, 0.0489e-2);  // the paper's h
  QTest::qWait(100);
  Keep(dialog->grab().toImage(), "2-fabric.png", -1);
  dialog->close();

  // 3. Obstacles ▸ form: a size larger, and the fabric laid on it.
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kObstacles, 0));
  FormEditor* form = window.obstacles()->form();
  ASSERT_TRUE(form->isVisible());
  ASSERT_TRUE(form->place("0, 0, 0", "0", "1.05")) << form->message().toStdString();
  ASSERT_TRUE(form->layFabricOn()) << form->message().toStdString();
  const double h = doc->scene().material.thickness;
  EXPECT_NEAR(
      doc->scene().fabric.elevation, 1.05 * kFormHeight + 0.5 * h + std::max(1e-3, h), 1e-6);
  QTest::qWait(200);
  Keep(window.grab().toImage(), "3-form.png", 500);

  // 4. Run ▸ Run, then look at the last step coloured by curvature.
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.findChild<QAction*>("run.run")->trigger();
  ASSERT_TRUE(finished.wait(600000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(summary.final_negative_pivots, 0);
  window.showStep(window.stepCount());
  ASSERT_TRUE(window.setField("curvature"));
  QTest::qWait(200);
  Keep(window.grab().toImage(), "4-run.png", 500);

  // 5. File ▸ Export ▸ Image of the view.
  const QString exported = temp_.filePath("export.png");
  QString error;
  ASSERT_TRUE(window.exportImage(exported, &error)) << error.toStdString();
  Keep(QImage(exported), "5-export.png", 500);

  // The README shows these pictures: each is there, at today's size.
  const QDir readme(
      QString::fromStdString((test::SourceDir() / "docs/images/quick-start").string()));
  for (const char* name : names_) {
    const QImage shown(readme.filePath(name));
    ASSERT_FALSE(shown.isNull()) << "docs/images/quick-start/" << name << " is missing";
    EXPECT_EQ(shown.size(), QImage(out_.filePath(name)).size()) << name;
  }
}

}  // namespace
}  // namespace drape
