// The workbench's menus walked as a user walks them: every menu a desktop
// program has (File, Edit, View, Units, Run, Help), the standard shortcuts,
// each action enabled when it can act and disabled when it cannot (nothing
// open, a run under way, no steps yet), and each one, triggered, doing what
// its name says — the file dialogs answered by the test (UserPrompts), the
// files it writes read back. Runs under xvfb-run -a.
#include <gtest/gtest.h>

#include <vtkCamera.h>
#include <vtkRenderer.h>
#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QUrl>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "support/test_paths.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/pattern_import_dialog.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_templates.h"
#include "ui/widgets/view_controller.h"
#include "ui/widgets/workbench_actions.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

QString SceneFile(const char* name) {
  return QString::fromStdString((test::ScenesDir() / name).string());
}

std::vector<std::string> MenuTitles(MainWindow& window) {
  std::vector<std::string> titles;
  for (QAction* top : window.menuBar()->actions())
    if (top->menu()) titles.push_back(top->menu()->title().remove('&').toStdString());
  return titles;
}

class Menus : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    ASSERT_TRUE(dir_.isValid());
    window_ = std::make_unique<MainWindow>();
    // The dialogs answered by the test: the next file or folder it names,
    // and the pages the window hands to the desktop collected.
    UserPrompts prompts;
    prompts.open_file = [this](QWidget*, const QString&, const QString&) { return answer_; };
    prompts.save_file = prompts.open_file;
    prompts.directory = [this](QWidget*, const QString&) { return answer_; };
    prompts.open_url = [this](const QUrl& url) {
      urls_.push_back(url);
      return true;
    };
    window_->actions()->setPrompts(prompts);
    window_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window_.get()));
  }
  void TearDown() override { window_.reset(); }

  QAction* Action(const char* name) const {
    auto* action = window_->findChild<QAction*>(name);
    EXPECT_NE(action, nullptr) << name;
    return action;
  }
  QMenu* Menu(const char* name) const { return window_->findChild<QMenu*>(name); }
  bool Enabled(const char* name) const { return Action(name)->isEnabled(); }
  // Runs the scene by the Run menu; true when it converged.
  bool RunToEnd() {
    QSignalSpy finished(window_.get(), &MainWindow::runFinished);
    Action("run.run")->trigger();
    if (!finished.wait(120000)) return false;
    return finished.takeFirst().at(0).value<SolveSummary>().IsComplete();
  }

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
  QString answer_;
  std::vector<QUrl> urls_;
};

TEST_F(Menus, EveryMenuWithTheStandardShortcuts) {
  EXPECT_EQ(MenuTitles(*window_),
            (std::vector<std::string>{"File", "Edit", "View", "Units", "Run", "Help"}));
  const std::pair<const char*, QKeySequence::StandardKey> standard[] = {
      {"file.new", QKeySequence::New},
      {"file.open", QKeySequence::Open},
      {"file.save", QKeySequence::Save},
      {"file.save_as", QKeySequence::SaveAs},
      {"file.quit", QKeySequence::Quit},
      {"edit.undo", QKeySequence::Undo},
      {"edit.redo", QKeySequence::Redo},
      {"help.manual", QKeySequence::HelpContents}};
  for (const auto& [name, key] : standard) {
    ASSERT_NE(Action(name), nullptr);
    EXPECT_EQ(Action(name)->shortcut(), QKeySequence(key)) << name;
  }
  for (const char* name : {"file.templates", "file.recent", "file.export"})
    EXPECT_NE(Menu(name), nullptr) << name;
}

// The catalogue's groups and titles are the menu's; every shipped scene is
// in it, so none is out of the user's reach.
TEST_F(Menus, TemplatesListEveryShippedSceneUnderItsTitle) {
  std::vector<std::string> files, titles;
  for (const TemplateGroup& group : SceneTemplates())
    for (const SceneTemplate& t : group.templates) {
      files.push_back(QFileInfo(t.file).fileName().toStdString());
      titles.push_back(t.title.toStdString());
      EXPECT_FALSE(t.description.isEmpty()) << t.title.toStdString();
    }
  for (const auto& scene : test::ExampleScenes())
    EXPECT_EQ(std::count(files.begin(), files.end(), scene.filename().string()), 1)
        << scene.filename();
  std::vector<std::string> shown;
  for (QAction* a : Menu("file.templates")->actions())
    if (!a->isSeparator()) shown.push_back(a->text().toStdString());
  EXPECT_EQ(shown, titles);
  EXPECT_EQ(titles.front(), "Blank: a square of fabric held along one edge");
}

// Nothing open: only what starts or opens a scene, and Help and Quit.
TEST_F(Menus, ActionsAreEnabledWhenTheyCanAct) {
  for (const char* name : {"file.new", "file.open", "file.quit", "help.manual", "help.about"})
    EXPECT_TRUE(Enabled(name)) << name;
  for (const char* name : {"file.save",
                           "file.save_as",
                           "file.import_pattern",
                           "file.export_image",
                           "file.export_vtu",
                           "run.run",
                           "run.pause",
                           "run.step",
                           "run.stop",
                           "edit.material",
                           "edit.undo",
                           "edit.redo"})
    EXPECT_FALSE(Enabled(name)) << name;

  ASSERT_TRUE(window_->openScene(SceneFile("strip-fold.json")));
  for (const char* name :
       {"file.save", "file.save_as", "file.import_pattern", "file.export_image", "run.run"})
    EXPECT_TRUE(Enabled(name)) << name;
  // No steps yet: nothing to export as a run.
  EXPECT_FALSE(Enabled("file.export_vtu"));
  EXPECT_FALSE(Enabled("file.export_animation"));

  // During a run: its controls, no edits, no other scene.
  QSignalSpy finished(window_.get(), &MainWindow::runFinished);
  Action("run.run")->trigger();
  ASSERT_TRUE(window_->isRunning());
  for (const char* name : {"run.pause", "run.stop"}) EXPECT_TRUE(Enabled(name)) << name;
  for (const char* name :
       {"file.new", "file.open", "file.save", "run.run", "edit.material", "file.export_vtu"})
    EXPECT_FALSE(Enabled(name)) << name;
  EXPECT_FALSE(Menu("file.templates")->isEnabled());
  ASSERT_TRUE(finished.wait(120000));
  EXPECT_TRUE(Enabled("file.export_vtu"));
  EXPECT_TRUE(Enabled("file.export_animation"));
  EXPECT_FALSE(Enabled("run.stop"));
}

TEST_F(Menus, FileActionsDoWhatTheySay) {
  // New: the blank scene, untitled.
  Action("file.new")->trigger();
  EXPECT_EQ(window_->document()->scene().name, "A square of fabric held along one edge");
  EXPECT_TRUE(window_->windowTitle().startsWith("untitled"));

  // A template by its title.
  for (QAction* a : Menu("file.templates")->actions())
    if (a->text() == "Cusick drape test") a->trigger();
  EXPECT_EQ(window_->document()->scene().name, "Cusick drape test of a cotton twill");

  // Open…: the file the dialog gives; it joins Open recent.
  answer_ = SceneFile("strip-fold.json");
  Action("file.open")->trigger();
  EXPECT_EQ(window_->document()->file(), answer_);
  QAction* recent = nullptr;
  for (QAction* a : Menu("file.recent")->actions())
    if (a->toolTip() == answer_) recent = a;
  ASSERT_NE(recent, nullptr);
  Action("file.new")->trigger();
  recent->trigger();
  EXPECT_EQ(window_->document()->file(), answer_);

  // Save as…: written where the dialog says, and read back the same scene.
  answer_ = dir_.filePath("copy.json");
  Action("file.save_as")->trigger();
  EXPECT_EQ(window_->document()->file(), answer_);
  ASSERT_TRUE(QFileInfo::exists(answer_));
  // Save: an edit written to the same file.
  Scene edited = window_->document()->scene();
  edited.name = "edited strip";
  window_->document()->apply("rename", edited);
  ASSERT_TRUE(window_->document()->isModified());
  answer_.clear();  // Save asks nothing for a scene that has its file
  Action("file.save")->trigger();
  EXPECT_FALSE(window_->document()->isModified());
  ASSERT_TRUE(window_->openScene(dir_.filePath("copy.json")));
  EXPECT_EQ(window_->document()->scene().name, "edited strip");

  // Import pattern…: the import dialog comes up.
  Action("file.import_pattern")->trigger();
  auto* import = window_->findChild<PatternImportDialog*>();
  ASSERT_NE(import, nullptr);
  EXPECT_TRUE(import->isVisible());
  import->close();

  // Export ▸ Image: a PNG of the view's size.
  answer_ = dir_.filePath("view.png");
  Action("file.export_image")->trigger();
  const QImage image(answer_);
  EXPECT_FALSE(image.isNull());
  EXPECT_GT(CountFabric(image), 100);

  // Export ▸ VTU and Animation, once there is a run.
  ASSERT_TRUE(RunToEnd());
  answer_ = dir_.filePath("vtu");
  QDir().mkpath(answer_);
  Action("file.export_vtu")->trigger();
  EXPECT_TRUE(QFileInfo::exists(dir_.filePath("vtu/run.pvd")));
  answer_ = dir_.filePath("fold.mp4");
  Action("file.export_animation")->trigger();
  EXPECT_GT(QFileInfo(answer_).size(), 1000);

  // Recover: an autosave of an edit comes back as that edit, unsaved.
  edited.name = "autosaved strip";
  window_->document()->apply("rename", edited);
  ASSERT_TRUE(window_->autosave());
  window_->document()->undoStack()->undo();
  Action("file.save")->trigger();  // nothing unsaved: replacing it asks nothing
  ASSERT_EQ(window_->document()->scene().name, "edited strip");
  QMenu* file = window_->menuBar()->actions().front()->menu();
  emit file->aboutToShow();
  ASSERT_TRUE(Enabled("file.recover"));
  Action("file.recover")->trigger();
  EXPECT_EQ(window_->document()->scene().name, "autosaved strip");
  EXPECT_TRUE(window_->document()->isModified());

  // Quit: with the changes saved, the window closes.
  answer_ = dir_.filePath("recovered.json");
  Action("file.save")->trigger();
  ASSERT_FALSE(window_->document()->isModified());
  Action("file.quit")->trigger();
  EXPECT_FALSE(window_->isVisible());
}

TEST_F(Menus, EditViewRunAndHelpActionsDoWhatTheySay) {
  ASSERT_TRUE(window_->openScene(SceneFile("strip-fold.json")));
  // Undo and Redo take an edit back and bring it again.
  const std::string name = window_->document()->scene().name;
  Scene edited = window_->document()->scene();
  edited.name = "renamed";
  window_->document()->apply("rename", edited);
  ASSERT_TRUE(Enabled("edit.undo"));
  Action("edit.undo")->trigger();
  EXPECT_EQ(window_->document()->scene().name, name);
  Action("edit.redo")->trigger();
  EXPECT_EQ(window_->document()->scene().name, "renamed");

  Action("edit.material")->trigger();
  auto* material = window_->findChild<MaterialDialog*>();
  ASSERT_NE(material, nullptr);
  EXPECT_TRUE(material->isVisible());
  material->close();

  Action("edit.pick")->trigger();
  EXPECT_TRUE(window_->viewport()->pickMode());
  window_->pickNear({0, 0, 0});
  EXPECT_EQ(window_->pickedNodes().size(), 1u);
  Action("edit.clear_picked")->trigger();
  EXPECT_TRUE(window_->pickedNodes().empty());
  Action("edit.pick")->trigger();
  EXPECT_FALSE(window_->viewport()->pickMode());

  // Run, then walk its steps from the View menu.
  ASSERT_TRUE(RunToEnd());
  const int steps = window_->stepCount();
  ASSERT_GT(steps, 2);
  Action("view.reference")->trigger();
  EXPECT_EQ(window_->currentStep(), 0);
  Action("view.next")->trigger();
  EXPECT_EQ(window_->currentStep(), 1);
  Action("view.last")->trigger();
  EXPECT_EQ(window_->currentStep(), steps);
  Action("view.previous")->trigger();
  EXPECT_EQ(window_->currentStep(), steps - 1);
  // Each camera action puts the camera on its own side of the part, as
  // `drape render --camera` does: front on −y, side on +x, top on +z, iso
  // along (1, −1, 0.8).
  const std::pair<const char*, Eigen::Vector3d> cameras[] = {
      {"view.camera_front", {0, -1, 0}},
      {"view.camera_side", {1, 0, 0}},
      {"view.camera_top", {0, 0, 1}},
      {"view.camera_iso", Eigen::Vector3d(1, -1, 0.8).normalized()}};
  for (const auto& [name, from] : cameras) {
    Action(name)->trigger();
    vtkCamera* camera = window_->view()->renderer()->renderer()->GetActiveCamera();
    Eigen::Vector3d position, focus;
    camera->GetPosition(position.data());
    camera->GetFocalPoint(focus.data());
    EXPECT_LT(((position - focus).normalized() - from).norm(), 1e-9) << name;
  }

  // Pause, Step and Stop while a run goes on: paused it takes one step at a
  // time; stopped it keeps the steps it has.
  QSignalSpy finished(window_.get(), &MainWindow::runFinished);
  Action("run.run")->trigger();
  Action("run.pause")->trigger();
  ASSERT_TRUE(window_->isPaused());
  EXPECT_EQ(Action("run.pause")->text().remove('&'), "Resume");
  QTest::qWait(300);
  const int before = window_->stepCount();
  Action("run.step")->trigger();
  QTRY_COMPARE_WITH_TIMEOUT(window_->stepCount(), before + 1, 30000);
  Action("run.stop")->trigger();
  ASSERT_TRUE(finished.wait(30000));
  EXPECT_FALSE(window_->isRunning());
  EXPECT_GE(window_->stepCount(), before + 1);

  // Help: the manual and the file reference handed to the desktop, files
  // that exist; About names the program and its version.
  Action("help.manual")->trigger();
  Action("help.format")->trigger();
  ASSERT_EQ(urls_.size(), 2u);
  EXPECT_TRUE(urls_[0].toLocalFile().endsWith("docs/workbench.md"));
  EXPECT_TRUE(urls_[1].toLocalFile().endsWith("docs/format.md"));
  for (const QUrl& url : urls_)
    EXPECT_TRUE(QFileInfo::exists(url.toLocalFile())) << url.toLocalFile().toStdString();
  Action("help.about")->trigger();
  auto* about = window_->findChild<QMessageBox*>("about");
  ASSERT_NE(about, nullptr);
  EXPECT_TRUE(about->text().contains("Drape Studio"));
  about->close();
}

}  // namespace
}  // namespace drape
