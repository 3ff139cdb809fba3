#include "ui/widgets/workbench_actions.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

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
#include "ui/widgets/unit_settings.h"

namespace drape {

WorkbenchActions::WorkbenchActions(MainWindow* window) : QObject(window), window_(window) {
  BuildFileMenu();
  SceneDocument* document = window_->document();
  QMenu* edit = window_->menuBar()->addMenu("&Edit");
  undo_ = document->undoStack()->createUndoAction(this, "&Undo");
  undo_->setShortcut(QKeySequence::Undo);
  redo_ = document->undoStack()->createRedoAction(this, "&Redo");
  redo_->setShortcut(QKeySequence::Redo);
  edit->addAction(undo_);
  edit->addAction(redo_);
  edit->addSeparator();
  material_ = edit->addAction("&Material…", this, [this, document] {
    auto* dialog = new MaterialDialog(document, window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setUnitSystem(window_->units()->system());
    connect(window_->units(), &UnitSettings::changed, dialog, &MaterialDialog::setUnitSystem);
    dialog->show();
  });
  pick_ = edit->addAction(
      "&Pick nodes", this, [this](bool on) { window_->picking()->setPickMode(on); });
  pick_->setCheckable(true);
  pick_->setShortcut(Qt::Key_P);
  edit->addAction("&Clear picked nodes", window_, &MainWindow::clearPicked);
  BuildToolBar();
  BuildViewMenu();
  window_->menuBar()->addMenu(window_->units()->menu(window_));
}

void WorkbenchActions::BuildFileMenu() {
  QMenu* file = window_->menuBar()->addMenu("&File");
  window_->documentController()->setRecentMenu(file->addMenu("Open &recent"));
  QMenu* templates = file->addMenu("&New from template");
  const QDir scenes(QString::fromStdString((ResourceDir() / "scenes").string()));
  for (const QString& name : scenes.entryList({"*.json"}, QDir::Files, QDir::Name))
    templates->addAction(QFileInfo(name).completeBaseName(),
                         window_,
                         [this, path = scenes.filePath(name)] { window_->newFromTemplate(path); });
  file->addAction("&Import pattern…", this, [this] {
    auto* dialog = new PatternImportDialog(window_->document(), window_);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
  });
  file->addAction("Recover autosaved scene", window_, &MainWindow::recoverAutosave);
}

void WorkbenchActions::BuildViewMenu() {
  QMenu* view = window_->menuBar()->addMenu("&View");
  MainWindow* w = window_;
  view->addAction("&Previous step", w, [w] { w->showStep(w->currentStep() - 1); })
      ->setShortcut(Qt::ALT | Qt::Key_Left);
  view->addAction("&Next step", w, [w] { w->showStep(w->currentStep() + 1); })
      ->setShortcut(Qt::ALT | Qt::Key_Right);
  view->addAction("&Reference state", w, [w] { w->showStep(0); })
      ->setShortcut(Qt::ALT | Qt::Key_Home);
  view->addAction("&Last step", w, [w] { w->showStep(w->stepCount()); })
      ->setShortcut(Qt::ALT | Qt::Key_End);
  view->addAction("P&lay", w, &MainWindow::play)->setShortcut(Qt::CTRL | Qt::Key_Space);
  view->addSeparator();
  // The camera fitted to the run again, from a direction of `drape render`.
  const std::pair<const char*, Qt::Key> cameras[] = {
      {"iso", Qt::Key_1}, {"front", Qt::Key_2}, {"top", Qt::Key_3}, {"side", Qt::Key_4}};
  for (const auto& [name, key] : cameras)
    view->addAction(
            QString("Camera &%1").arg(name),
            w,
            [w, camera = std::string(name)] { w->setCamera(QString::fromStdString(camera)); })
        ->setShortcut(Qt::CTRL | key);
}

void WorkbenchActions::BuildToolBar() {
  MainWindow* w = window_;
  QToolBar* bar = w->addToolBar("Run");
  open_ = bar->addAction("Open…", w, [w] {
    const QString file = QFileDialog::getOpenFileName(w, "Open scene", {}, "Scenes (*.json)");
    if (!file.isEmpty()) w->openScene(file);
  });
  open_->setShortcut(QKeySequence::Open);
  QAction* save = bar->addAction("Save", w, [w] {
    if (w->document()->file().isEmpty()) {
      const QString file = QFileDialog::getSaveFileName(w, "Save scene", {}, "Scenes (*.json)");
      if (!file.isEmpty()) w->saveScene(file);
    } else {
      w->saveScene();
    }
  });
  save->setShortcut(QKeySequence::Save);
  QAction* save_as = bar->addAction("Save as…", w, [w] {
    const QString file = QFileDialog::getSaveFileName(w, "Save scene as", {}, "Scenes (*.json)");
    if (!file.isEmpty()) w->saveScene(file);
  });
  save_as->setShortcut(QKeySequence::SaveAs);
  run_ = bar->addAction("Run", w, &MainWindow::run);
  run_->setShortcut(Qt::Key_F5);
  pause_ = bar->addAction("Pause", w, &MainWindow::pauseOrResume);
  pause_->setShortcut(Qt::Key_F6);
  step_ = bar->addAction("Step", w, &MainWindow::stepOnce);
  step_->setShortcut(Qt::Key_F7);
  stop_ = bar->addAction("Stop", w, &MainWindow::stop);
  stop_->setShortcut(Qt::Key_Escape);
  bar->addSeparator();
  QAction* export_image = bar->addAction("Export image…", w, [w] {
    const QString file = QFileDialog::getSaveFileName(w, "Export image", {}, "PNG (*.png)");
    QString error;
    if (!file.isEmpty() && !w->exportImage(file, &error)) ShowError(w, "Export failed", error);
  });
  export_image->setShortcut(Qt::CTRL | Qt::Key_E);
  QAction* export_vtu = bar->addAction("Export VTU…", w, [w] {
    const QString dir = QFileDialog::getExistingDirectory(w, "Export the run as VTU into");
    QString error;
    if (!dir.isEmpty() && !w->exportVtu(dir, &error) && !error.isEmpty())
      ShowError(w, "Export failed", error);
  });
  export_vtu->setToolTip("every step as .vtu with a run.pvd ParaView plays");
  bar->addAction("Export animation…", w, [w] {
    const QString file =
        QFileDialog::getSaveFileName(w, "Export animation", {}, "Movies (*.mp4 *.gif *.ogv)");
    QString error;
    if (!file.isEmpty() && !w->exportAnimation(file, 25, &error) && !error.isEmpty())
      ShowError(w, "Export failed", error);
  });
}

void WorkbenchActions::update(bool loaded, bool running, bool paused, bool estimating) {
  SceneDocument* document = window_->document();
  open_->setEnabled(!running);
  run_->setEnabled(loaded && !running);
  material_->setEnabled(!running && loaded);
  undo_->setEnabled(!running && document->undoStack()->canUndo());
  redo_->setEnabled(!running && document->undoStack()->canRedo());
  pause_->setEnabled(running);
  pause_->setText(paused ? "Resume" : "Pause");
  // One step of the run: the estimate's runs on coarser meshes have none.
  step_->setEnabled(running && paused && !estimating);
  stop_->setEnabled(running);
}

}  // namespace drape
