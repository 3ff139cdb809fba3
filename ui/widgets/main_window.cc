#include "ui/widgets/main_window.h"

#include <QCloseEvent>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

#include "ui/widgets/editor_docks.h"
#include "ui/widgets/error_box.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/preview_controller.h"
#include "ui/widgets/run_controller.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/stages_panel.h"
#include "ui/widgets/unit_settings.h"
#include "ui/widgets/vtk_viewport.h"
#include "ui/widgets/workbench_actions.h"

namespace drape {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle("Drape Studio");
  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  viewport_ = new VtkViewport(central);
  viewport_->setMinimumSize(640, 400);
  layout->addWidget(viewport_, 1);
  view_ = new ViewController(viewport_, central, this);
  layout->addWidget(view_->bar());
  setCentralWidget(central);
  document_ = new SceneDocument(this);
  documents_ = new DocumentController(document_, this, this);
  picking_ = new PickingController(viewport_, view_, this);
  handles_ = new HandleController(viewport_, document_, view_, this);
  monitor_ = new RunMonitor(view_, this, statusBar(), this);
  units_ = new UnitSettings(this);
  previews_ = new PreviewController(this);
  docks_ = new EditorDocks(document_, monitor_, this);
  // Handles show while their editor is up: a path's with the stages, an
  // obstacle's with the obstacles, an outline's with the properties.
  connect(docks_, &EditorDocks::stagesShown, handles_, &HandleController::setStagesShown);
  connect(docks_, &EditorDocks::grippersShown, handles_, &HandleController::setGrippersShown);
  connect(docks_, &EditorDocks::obstaclesShown, handles_, &HandleController::setObstaclesShown);
  connect(docks_, &EditorDocks::propertiesShown, handles_, &HandleController::setPropertiesShown);
  ShowUnits(units_->system());
  connect(units_, &UnitSettings::changed, this, &MainWindow::ShowUnits);
  connect(documents_, &DocumentController::opened, units_, &UnitSettings::followSceneFile);
  auto say = [this](const QString& text) { statusBar()->showMessage(text); };
  connect(previews_, &PreviewController::previewStep, this, [this](int g, auto model, auto step) {
    if (g == previews_->generation()) view_->setGhost(g, std::move(model), std::move(step));
  });
  connect(previews_, &PreviewController::previewFinished, this, [say] {
    say("draft preview ready — Run to refine");
  });
  connect(previews_, &PreviewController::previewFailed, this, [say](int, const QString& why) {
    say("no draft preview: " + why);
  });
  connect(documents_, &DocumentController::message, this, say);
  connect(view_, &ViewController::message, this, say);
  connect(picking_, &PickingController::message, this, say);
  connect(handles_, &HandleController::message, this, say);
  // A complete run's end can be dragged by its grippers; let go, it is solved again.
  connect(monitor_->controller(), &RunController::solved, handles_, &HandleController::setSolved);
  connect(handles_, &HandleController::gripperDragApplied, this, &MainWindow::run);
  connect(monitor_, &RunMonitor::message, this, say);
  connect(monitor_, &RunMonitor::controlsChanged, this, &MainWindow::UpdateControls);
  connect(monitor_, &RunMonitor::finished, this, &MainWindow::OnFinished);
  connect(monitor_, &RunMonitor::failed, this, [this](const QString& message) {
    ShowError(this, "The run could not start", message);
  });
  connect(documents_, &DocumentController::accepted, this, &MainWindow::OnAccepted);
  // The editors that can use picked nodes hear of them.
  connect(picking_, &PickingController::pickedChanged, docks_, &EditorDocks::setPicked);
  connect(stages()->moves(), &MoveEditor::moveSelected, handles_, &HandleController::selectMove);
  connect(
      obstacles(), &ObstaclesPanel::obstacleSelected, handles_, &HandleController::selectObstacle);
  actions_ = new WorkbenchActions(this);
  connect(tree(), &ModelTree::opened, this, [this](ModelTree::Part part, int, int) {
    if (part == ModelTree::Part::kMaterial && actions_->material()->isEnabled())
      actions_->material()->trigger();
  });
  UpdateControls();
  resize(1280, 960);
  QSettings settings;
  if (settings.contains("window/geometry"))
    restoreGeometry(settings.value("window/geometry").toByteArray());
  if (settings.contains("window/docks")) restoreState(settings.value("window/docks").toByteArray());
}

MainWindow::~MainWindow() {
  previews_->cancel();
  delete monitor_;  // stops the run and joins its thread before the window goes
  monitor_ = nullptr;
  // The renderer's actors (and the handles in it) live in the viewport's
  // window: released while the GL context exists.
  view_->releaseRenderer();
}

// The document's scene was modelled: the view shows it with the document's
// model (the one the panels show); picks on other nodes go. An edit keeps
// the last run's end in view (stale) and starts a draft preview of the
// edited scene, its ghost drawn over it.
void MainWindow::OnAccepted(bool renumbered, bool edited) {
  if (renumbered) picking_->clear();
  view_->setScene(document_->scene(), document_->model(), edited);
  monitor_->estimateLabel()->clear();
  if (edited)
    previews_->request(document_->scene());
  else
    previews_->cancel();
  UpdateControls();
}

void MainWindow::ShowUnits(UnitSystem system) {
  docks_->setUnitSystem(system);
  monitor_->setUnitSystem(system);
  view_->setUnitSystem(system);
}

void MainWindow::UpdateControls() {
  const bool running = isRunning();
  // A run works on the scene it started with: no edits meanwhile.
  docks_->setEditable(!running);
  if (actions_)
    actions_->update(view_->model() != nullptr, running, isPaused(), monitor_->isEstimating());
}

void MainWindow::run() {
  if (!view_->model() || isRunning()) return;
  handles_->setEditable(false);  // no edits while the run goes on
  previews_->cancel();           // the run refines what the preview drafted
  view_->clearGhost();
  monitor_->start(view_->scene());
  document_->setLocked(true);
  UpdateControls();
}

void MainWindow::OnFinished(const SolveSummary& summary) {
  document_->setLocked(false);
  UpdateControls();
  handles_->setEditable(true);
  emit runFinished(summary);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!documents_->mayClose()) return event->ignore();
  stop();
  QSettings().setValue("window/geometry", saveGeometry());
  QSettings().setValue("window/docks", saveState());
  documents_->closed();
  event->accept();
}

bool MainWindow::Report(const ExportOutcome& outcome, QString* error) {
  if (outcome.written || outcome.cancelled)
    statusBar()->showMessage(outcome.message);
  else if (error)
    *error = outcome.message;
  return outcome.written;
}

bool MainWindow::exportImage(const QString& file, QString* error) {
  if (!view_->model()) return false;
  return Report(ExportController(this).Image(view_->exportedRun(isRunning()), view_->look(), file),
                error);
}

bool MainWindow::exportAnimation(const QString& file, double fps, QString* error) {
  return Report(
      ExportController(this).Animation(view_->exportedRun(isRunning()), view_->look(), file, fps),
      error);
}

bool MainWindow::exportVtu(const QString& directory, QString* error) {
  return Report(ExportController(this).Vtu(view_->exportedRun(isRunning()), directory), error);
}

}  // namespace drape
