#include "ui/widgets/workbench_actions.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

#include <exception>
#include <string>
#include <utility>

#include "core/io/resource_dir.h"
#include "ui/widgets/document_controller.h"
#include "ui/widgets/error_box.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/pattern_import_dialog.h"
#include "ui/widgets/picking_controller.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_templates.h"
#include "ui/widgets/unit_settings.h"

namespace drape {
namespace {

const char kScenes[] = "Scenes (*.json)";

// The project's documents: beside the resources in a checkout and an install.
QString DocumentPath(const char* name) {
  return QDir::cleanPath(QString::fromStdString((ResourceDir() / ".." / "docs" / name).string()));
}

}  // namespace

WorkbenchActions::WorkbenchActions(MainWindow* window) : QObject(window), window_(window) {
  BuildFileMenu();
  BuildEditMenu();
  BuildViewMenu();
  window_->menuBar()->addMenu(window_->units()->menu(window_));
  BuildRunMenu();
  BuildHelpMenu();
  BuildToolBar();
}

QAction* WorkbenchActions::Add(QMenu* menu, const char* name, const QString& text) {
  QAction* action = menu->addAction(text);
  action->setObjectName(name);
  return action;
}

bool WorkbenchActions::MayReplace() {
  return window_->documentController()->mayClose();
}

void WorkbenchActions::BuildFileMenu() {
  MainWindow* w = window_;
  QMenu* file = w->menuBar()->addMenu("&File");
  file->setToolTipsVisible(true);
  new_ = Add(file, "file.new", "&New");
  new_->setShortcut(QKeySequence::New);
  new_->setToolTip("a new scene: a square of fabric held along one edge, ready to make your own");
  connect(new_, &QAction::triggered, this, [this, w] {
    if (!MayReplace()) return;
    try {
      w->newFromTemplate(BlankTemplate().file);
    } catch (const std::exception& e) {
      ShowError(w, "Cannot start a new scene", QString::fromStdString(e.what()));
    }
  });
  templates_ = file->addMenu("New from &template");
  templates_->setObjectName("file.templates");
  BuildTemplateMenu(templates_);
  open_ = Add(file, "file.open", "&Open…");
  open_->setShortcut(QKeySequence::Open);
  connect(open_, &QAction::triggered, this, [this, w] {
    if (!MayReplace()) return;
    const QString name = prompts_.open_file(w, "Open scene", kScenes);
    if (!name.isEmpty()) w->openScene(name);
  });
  recent_ = file->addMenu("Open &recent");
  recent_->setObjectName("file.recent");
  w->documentController()->setRecentMenu(recent_);
  file->addSeparator();
  save_ = Add(file, "file.save", "&Save");
  save_->setShortcut(QKeySequence::Save);
  connect(save_, &QAction::triggered, this, [this] { SaveScene(false); });
  save_as_ = Add(file, "file.save_as", "Save &as…");
  save_as_->setShortcut(QKeySequence::SaveAs);
  connect(save_as_, &QAction::triggered, this, [this] { SaveScene(true); });
  file->addSeparator();
  import_ = Add(file, "file.import_pattern", "&Import pattern…");
  import_->setToolTip("a piece of a DXF-AAMA pattern file as the fabric's outline");
  connect(import_, &QAction::triggered, this, [w] {
    auto* dialog = new PatternImportDialog(w->document(), w);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
  });
  export_ = file->addMenu("&Export");
  export_->setObjectName("file.export");
  BuildExportMenu(export_);
  file->addSeparator();
  recover_ = Add(file, "file.recover", "Recover autosaved scene");
  recover_->setToolTip(
      "the scene as it was autosaved before the workbench last closed unexpectedly");
  connect(recover_, &QAction::triggered, this, [this, w] {
    if (MayReplace()) w->recoverAutosave();
  });
  // An autosave appears while the workbench runs: looked for when the menu opens.
  connect(file, &QMenu::aboutToShow, this, [this] {
    recover_->setEnabled(!window_->isRunning() && QFileInfo::exists(MainWindow::autosavePath()));
  });
  file->addSeparator();
  quit_ = Add(file, "file.quit", "&Quit");
  quit_->setShortcut(QKeySequence::Quit);
  quit_->setMenuRole(QAction::QuitRole);
  connect(quit_, &QAction::triggered, w, &QWidget::close);  // asks to save unsaved changes
}

void WorkbenchActions::BuildTemplateMenu(QMenu* menu) {
  MainWindow* w = window_;
  try {
    for (const TemplateGroup& group : SceneTemplates()) {
      menu->addSection(group.title);
      for (const SceneTemplate& entry : group.templates) {
        QAction* action = menu->addAction(entry.title);
        action->setToolTip(entry.description);
        action->setData(entry.file);
        connect(action, &QAction::triggered, this, [this, w, file = entry.file] {
          if (MayReplace()) w->newFromTemplate(file);
        });
      }
    }
    menu->setToolTipsVisible(true);
  } catch (const std::exception& e) {
    // The workbench still opens; the menu says why it is empty.
    menu->addAction(QString("No templates: %1").arg(e.what()))->setEnabled(false);
  }
}

void WorkbenchActions::BuildExportMenu(QMenu* menu) {
  MainWindow* w = window_;
  export_image_ = Add(menu, "file.export_image", "&Image of the view…");
  export_image_->setShortcut(Qt::CTRL | Qt::Key_E);
  connect(export_image_, &QAction::triggered, this, [this, w] {
    const QString file = prompts_.save_file(w, "Export image", "PNG (*.png)");
    QString error;
    if (!file.isEmpty() && !w->exportImage(file, &error)) ShowError(w, "Export failed", error);
  });
  export_vtu_ = Add(menu, "file.export_vtu", "Run as &VTU (ParaView)…");
  export_vtu_->setToolTip("every step as .vtu with a run.pvd ParaView plays");
  connect(export_vtu_, &QAction::triggered, this, [this, w] {
    const QString dir = prompts_.directory(w, "Export the run as VTU into");
    QString error;
    if (!dir.isEmpty() && !w->exportVtu(dir, &error) && !error.isEmpty())
      ShowError(w, "Export failed", error);
  });
  export_animation_ = Add(menu, "file.export_animation", "&Animation…");
  export_animation_->setToolTip("the run as a movie (MP4, GIF, OGV)");
  connect(export_animation_, &QAction::triggered, this, [this, w] {
    const QString file = prompts_.save_file(w, "Export animation", "Movies (*.mp4 *.gif *.ogv)");
    QString error;
    if (!file.isEmpty() && !w->exportAnimation(file, 25, &error) && !error.isEmpty())
      ShowError(w, "Export failed", error);
  });
}

void WorkbenchActions::SaveScene(bool ask_where) {
  MainWindow* w = window_;
  if (ask_where || w->document()->file().isEmpty()) {
    const QString file = prompts_.save_file(w, ask_where ? "Save scene as" : "Save scene", kScenes);
    if (!file.isEmpty()) w->saveScene(file);
  } else {
    w->saveScene();
  }
}

void WorkbenchActions::BuildEditMenu() {
  SceneDocument* document = window_->document();
  QMenu* edit = window_->menuBar()->addMenu("&Edit");
  undo_ = document->undoStack()->createUndoAction(this, "&Undo");
  undo_->setObjectName("edit.undo");
  undo_->setShortcut(QKeySequence::Undo);
  redo_ = document->undoStack()->createRedoAction(this, "&Redo");
  redo_->setObjectName("edit.redo");
  redo_->setShortcut(QKeySequence::Redo);
  edit->addAction(undo_);
  edit->addAction(redo_);
  edit->addSeparator();
  material_ = Add(edit, "edit.material", "&Material…");
  connect(material_, &QAction::triggered, this, [this, document] {
    auto* dialog = new MaterialDialog(document, window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setUnitSystem(window_->units()->system());
    connect(window_->units(), &UnitSettings::changed, dialog, &MaterialDialog::setUnitSystem);
    dialog->show();
  });
  pick_ = Add(edit, "edit.pick", "&Pick nodes");
  pick_->setCheckable(true);
  pick_->setShortcut(Qt::Key_P);
  connect(pick_, &QAction::toggled, this, [this](bool on) { window_->picking()->setPickMode(on); });
  clear_picked_ = Add(edit, "edit.clear_picked", "&Clear picked nodes");
  connect(clear_picked_, &QAction::triggered, window_, &MainWindow::clearPicked);
}

void WorkbenchActions::BuildViewMenu() {
  QMenu* view = window_->menuBar()->addMenu("&View");
  MainWindow* w = window_;
  const auto step = [&](const char* name, const QString& text, QKeyCombination key, auto go) {
    QAction* action = Add(view, name, text);
    action->setShortcut(key);
    connect(action, &QAction::triggered, w, go);
  };
  step("view.previous", "&Previous step", Qt::ALT | Qt::Key_Left, [w] {
    w->showStep(w->currentStep() - 1);
  });
  step("view.next", "&Next step", Qt::ALT | Qt::Key_Right, [w] {
    w->showStep(w->currentStep() + 1);
  });
  step("view.reference", "&Reference state", Qt::ALT | Qt::Key_Home, [w] { w->showStep(0); });
  step("view.last", "&Last step", Qt::ALT | Qt::Key_End, [w] { w->showStep(w->stepCount()); });
  step("view.play", "P&lay", Qt::CTRL | Qt::Key_Space, [w] { w->play(); });
  view->addSeparator();
  // The camera fitted to the run again, from a direction of `drape render`.
  const std::pair<const char*, Qt::Key> cameras[] = {
      {"iso", Qt::Key_1}, {"front", Qt::Key_2}, {"top", Qt::Key_3}, {"side", Qt::Key_4}};
  for (const auto& [name, key] : cameras) {
    QAction* action = Add(view, "", QString("Camera &%1").arg(name));
    action->setObjectName(QString("view.camera_%1").arg(name));
    action->setShortcut(Qt::CTRL | key);
    connect(action, &QAction::triggered, w, [w, camera = QString(name)] { w->setCamera(camera); });
  }
}

void WorkbenchActions::BuildRunMenu() {
  MainWindow* w = window_;
  QMenu* run = w->menuBar()->addMenu("&Run");
  run_ = Add(run, "run.run", "&Run");
  run_->setShortcut(Qt::Key_F5);
  run_->setToolTip("solve the scene, step by step, showing each step as it comes");
  connect(run_, &QAction::triggered, w, &MainWindow::run);
  pause_ = Add(run, "run.pause", "&Pause");
  pause_->setShortcut(Qt::Key_F6);
  connect(pause_, &QAction::triggered, w, &MainWindow::pauseOrResume);
  step_ = Add(run, "run.step", "&Step");
  step_->setShortcut(Qt::Key_F7);
  step_->setToolTip("while paused: one more step");
  connect(step_, &QAction::triggered, w, &MainWindow::stepOnce);
  stop_ = Add(run, "run.stop", "St&op");
  stop_->setShortcut(Qt::Key_Escape);
  stop_->setToolTip("stop the run, keeping the steps it has");
  connect(stop_, &QAction::triggered, w, &MainWindow::stop);
}

void WorkbenchActions::BuildHelpMenu() {
  MainWindow* w = window_;
  QMenu* help = w->menuBar()->addMenu("&Help");
  QAction* manual = Add(help, "help.manual", "Drape Studio &manual");
  manual->setShortcut(QKeySequence::HelpContents);
  connect(manual, &QAction::triggered, this, [this] {
    prompts_.open_url(QUrl::fromLocalFile(DocumentPath("workbench.md")));
  });
  QAction* format = Add(help, "help.format", "Scene &file reference");
  connect(format, &QAction::triggered, this, [this] {
    prompts_.open_url(QUrl::fromLocalFile(DocumentPath("format.md")));
  });
  help->addSeparator();
  QAction* about = Add(help, "help.about", "&About Drape Studio");
  about->setMenuRole(QAction::AboutRole);
  connect(about, &QAction::triggered, this, &WorkbenchActions::ShowAbout);
}

void WorkbenchActions::ShowAbout() {
  auto* box = new QMessageBox(
      QMessageBox::Information,
      "About Drape Studio",
      QString("<b>Drape Studio %1</b><p>A workbench for apparel engineers: a fabric part "
              "draped, picked up, folded and laid down, simulated as a nonlinear shell "
              "(Simo–Fox; Eischen, Deng &amp; Clapp, IEEE CG&amp;A 1996).</p>"
              "<p>Built with Qt %2 and VTK.</p>")
          .arg(QApplication::applicationVersion().isEmpty() ? "0.1.0"
                                                            : QApplication::applicationVersion(),
               qVersion()),
      QMessageBox::Ok,
      window_);
  box->setObjectName("about");
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->show();  // not modal: a script's run never waits on it
}

void WorkbenchActions::BuildToolBar() {
  QToolBar* bar = window_->addToolBar("Run");
  bar->setObjectName("toolbar");
  for (QAction* action : {open_, save_, save_as_}) bar->addAction(action);
  bar->addSeparator();
  for (QAction* action : {run_, pause_, step_, stop_}) bar->addAction(action);
  bar->addSeparator();
  for (QAction* action : {export_image_, export_vtu_, export_animation_}) bar->addAction(action);
}

void WorkbenchActions::update(bool loaded, bool running, bool paused, bool estimating) {
  SceneDocument* document = window_->document();
  const bool idle = !running;
  const bool has_steps = window_->stepCount() > 0;
  for (QAction* a : {new_, open_}) a->setEnabled(idle);
  recover_->setEnabled(idle && QFileInfo::exists(MainWindow::autosavePath()));
  templates_->setEnabled(idle);
  recent_->setEnabled(idle && !recent_->isEmpty());
  save_->setEnabled(idle && loaded);
  save_as_->setEnabled(idle && loaded);
  import_->setEnabled(idle && loaded);
  export_->setEnabled(loaded);
  export_image_->setEnabled(loaded);
  export_vtu_->setEnabled(idle && has_steps);
  export_animation_->setEnabled(idle && has_steps);
  run_->setEnabled(loaded && idle);
  material_->setEnabled(idle && loaded);
  pick_->setEnabled(loaded);
  clear_picked_->setEnabled(loaded);
  undo_->setEnabled(idle && document->undoStack()->canUndo());
  redo_->setEnabled(idle && document->undoStack()->canRedo());
  pause_->setEnabled(running);
  pause_->setText(paused ? "&Resume" : "&Pause");
  // One step of the run: the estimate's runs on coarser meshes have none.
  step_->setEnabled(running && paused && !estimating);
  stop_->setEnabled(running);
}

}  // namespace drape
