#include "ui/widgets/main_window.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QListWidget>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

#include "ui/widgets/error_box.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/preview_controller.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/run_controller.h"
#include "ui/widgets/run_plot.h"
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
  BuildDocks();
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
  connect(picking_, &PickingController::pickedChanged, this, [this](auto& nodes, auto& at) {
    supports_->setPickedNodes(nodes, at);
    grippers_->setPickedNodes(nodes, at);
    loads_->setPickedNodes(nodes, at);
    probes_->setPicked(at);
  });
  connect(stages_->moves(), &MoveEditor::moveSelected, handles_, &HandleController::selectMove);
  connect(
      obstacles_, &ObstaclesPanel::obstacleSelected, handles_, &HandleController::selectObstacle);
  connect(tree_, &ModelTree::chosen, this, [this](ModelTree::Part part, int index, int move) {
    ShowEditor(static_cast<int>(part), index, move);
  });
  actions_ = new WorkbenchActions(this);
  connect(tree_, &ModelTree::opened, this, [this](ModelTree::Part part, int, int) {
    if (part == ModelTree::Part::kMaterial && actions_->material()->isEnabled())
      actions_->material()->trigger();
  });
  UpdateControls();
  // Seven editors share the left dock area: their tabs stand on its side.
  setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
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

void MainWindow::BuildDocks() {
  tree_ = new ModelTree(document_, this);
  tree_->setMinimumHeight(170);
  auto* tree_dock = new QDockWidget("Scene", this);
  tree_dock->setObjectName("Scene");
  tree_dock->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, tree_dock);
  properties_ = new PropertyPanel(document_, this);
  QDockWidget* properties_dock = AddPanel("Properties", properties_, nullptr);
  // The tree above, the editors tabbed below it.
  splitDockWidget(tree_dock, properties_dock, Qt::Vertical);
  supports_ = new HoldsPanel(HoldsPanel::Role::kSupports, document_, this);
  QDockWidget* supports_dock = AddPanel("Supports", supports_, properties_dock);
  grippers_ = new HoldsPanel(HoldsPanel::Role::kGrippers, document_, this);
  QDockWidget* grippers_dock = AddPanel("Grippers", grippers_, properties_dock);
  loads_ = new LoadsPanel(document_, this);
  QDockWidget* loads_dock = AddPanel("Loads", loads_, properties_dock);
  obstacles_ = new ObstaclesPanel(document_, this);
  QDockWidget* obstacles_dock = AddPanel("Obstacles", obstacles_, properties_dock);
  stages_ = new StagesPanel(document_, this);
  QDockWidget* stages_dock = AddPanel("Stages", stages_, properties_dock);
  probes_ = new ProbesPanel(document_, this);
  QDockWidget* probes_dock = AddPanel("Probes", probes_, properties_dock);
  // In ModelTree::Part's order.
  editor_docks_ = {properties_dock,
                   properties_dock,
                   supports_dock,
                   grippers_dock,
                   obstacles_dock,
                   stages_dock,
                   probes_dock,
                   properties_dock,
                   loads_dock};
  properties_dock->raise();
  resizeDocks({tree_dock, properties_dock}, {220, 700}, Qt::Vertical);
  // Handles show while their editor is up: a path's with the stages, an
  // obstacle's with the obstacles. (A dock tabbed behind another still says
  // isVisible(); the signal says when its tab is selected or unselected.)
  connect(
      stages_dock, &QDockWidget::visibilityChanged, handles_, &HandleController::setStagesShown);
  connect(grippers_dock,
          &QDockWidget::visibilityChanged,
          handles_,
          &HandleController::setGrippersShown);
  connect(obstacles_dock,
          &QDockWidget::visibilityChanged,
          handles_,
          &HandleController::setObstaclesShown);
  QDockWidget* plot_dock = AddPlot("Run", monitor_->plot(), nullptr);
  AddPlot("Probe plot", monitor_->probePlot(), plot_dock);
  AddPlot("Residuals", monitor_->residualPlot(), plot_dock);
  AddPlot("Reactions", monitor_->reactionPlot(), plot_dock);
  plot_dock->raise();
}

QDockWidget* MainWindow::AddPanel(const QString& title, QWidget* panel, QDockWidget* tab_with) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(title);  // for saveState
  dock->setWidget(panel);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  if (tab_with) tabifyDockWidget(tab_with, dock);
  return dock;
}

QDockWidget* MainWindow::AddPlot(const QString& title, QWidget* plot, QDockWidget* tab_with) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(title);
  dock->setWidget(plot);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  if (tab_with) tabifyDockWidget(tab_with, dock);
  return dock;
}

// The editor of what the model tree chose, raised, with the item selected.
void MainWindow::ShowEditor(int part, int index, int move) {
  if (part < 0 || part >= static_cast<int>(editor_docks_.size())) return;
  editor_docks_[part]->raise();
  if (index < 0) return;
  switch (static_cast<ModelTree::Part>(part)) {
    case ModelTree::Part::kSupports:
      return supports_->list()->setCurrentRow(index);
    case ModelTree::Part::kGrippers:
      return grippers_->list()->setCurrentRow(index);
    case ModelTree::Part::kObstacles:
      return obstacles_->list()->setCurrentRow(index);
    case ModelTree::Part::kStages:
      stages_->list()->setCurrentRow(index);
      if (move >= 0) stages_->moves()->list()->setCurrentRow(move);
      return;
    case ModelTree::Part::kProbes:
      return probes_->list()->setCurrentRow(index);
    case ModelTree::Part::kLoads:
      return loads_->list()->setCurrentRow(index);
    default:
      return;
  }
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
  properties_->setUnitSystem(system);
  loads_->setUnitSystem(system);
  supports_->setUnitSystem(system);
  grippers_->setUnitSystem(system);
  probes_->setUnitSystem(system);
  obstacles_->setUnitSystem(system);
  tree_->setUnitSystem(system);
  stages_->moves()->setUnitSystem(system);
  monitor_->probePlot()->setUnitSystem(system);
  monitor_->reactionPlot()->setUnitSystem(system);
  view_->setUnitSystem(system);
}

void MainWindow::UpdateControls() {
  const bool running = isRunning();
  // A run works on the scene it started with: no edits meanwhile.
  for (QWidget* editor : std::initializer_list<QWidget*>{
           properties_, stages_, supports_, grippers_, obstacles_, loads_, probes_})
    editor->setEnabled(!running);
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
