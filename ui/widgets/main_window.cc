#include "ui/widgets/main_window.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <QAction>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

#include "core/io/resource_dir.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/obstacle_anchor.h"
#include "core/model/outline_geometry.h"
#include "core/solve/path_handles.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/error_estimate_label.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/material_dialog.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/path_handles.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/run_controller.h"
#include "ui/widgets/run_plot.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_keeper.h"
#include "ui/widgets/stages_panel.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// Errors are shown without blocking: a run started by a script must not
// wait for someone to click OK.
// The menu shows the choice made by a call, without calling back.
void ShowChoice(QComboBox* box, const QString& data) {
  const int index = box->findData(data);
  if (index < 0 || index == box->currentIndex()) return;
  const QSignalBlocker block(box);
  box->setCurrentIndex(index);
}

void ShowError(QWidget* parent, const QString& title, const QString& message) {
  auto* box = new QMessageBox(QMessageBox::Critical, title, message, QMessageBox::Ok, parent);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->show();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  qRegisterMetaType<drape::Scene>();
  qRegisterMetaType<drape::SolveSummary>();
  qRegisterMetaType<drape::ErrorEstimate>();
  qRegisterMetaType<std::shared_ptr<const drape::StepState>>();
  runs_ = new RunController(this);
  connect(runs_, &RunController::stepConverged, this, &MainWindow::onStep);
  connect(runs_, &RunController::estimating, this, &MainWindow::onEstimating);
  connect(runs_, &RunController::estimated, this, &MainWindow::onErrorEstimated);
  connect(runs_, &RunController::failed, this, &MainWindow::onFailed);
  connect(runs_, &RunController::finished, this, &MainWindow::onFinished);
  setWindowTitle("Drape Studio");
  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  viewport_ = new VtkViewport(central);
  viewport_->setMinimumSize(640, 400);
  layout->addWidget(viewport_, 1);
  auto* timeline = new QHBoxLayout;
  timeline_ = new QSlider(Qt::Horizontal, central);
  timeline_->setRange(0, 0);
  step_label_ = new QLabel("no scene", central);
  step_label_->setMinimumWidth(260);
  field_ = new QComboBox(central);
  field_->addItem("fabric colours", "");
  for (const auto& f : Fields()) field_->addItem(f.title, f.name);
  colour_map_ = new QComboBox(central);
  for (ColourMap m : {ColourMap::kViridis, ColourMap::kRainbow})
    colour_map_->addItem(ToString(m), ToString(m));
  colour_map_->setToolTip(
      "Colours of the field: viridis (perceptually uniform, reads in grey) or the rainbow");
  auto* play = new QAction("Play", this);
  connect(play, &QAction::triggered, this, &MainWindow::play);
  auto* play_button = new QToolButton(central);
  play_button->setDefaultAction(play);
  timeline->addWidget(play_button);
  timeline->addWidget(timeline_, 1);
  timeline->addWidget(step_label_);
  timeline->addWidget(field_);
  timeline->addWidget(colour_map_);
  player_ = new QTimer(this);
  player_->setInterval(40);
  connect(player_, &QTimer::timeout, this, [this] {
    if (currentStep() >= stepCount()) return player_->stop();
    timeline_->setValue(currentStep() + 1);
  });
  connect(field_, &QComboBox::currentIndexChanged, this, [this](int) {
    setField(field_->currentData().toString());
  });
  connect(colour_map_, &QComboBox::currentIndexChanged, this, [this](int) {
    setColourMap(colour_map_->currentData().toString());
  });
  layout->addLayout(timeline);
  setCentralWidget(central);
  document_ = new SceneDocument(this);
  tree_ = new ModelTree(document_, this);
  tree_->setMinimumHeight(170);
  auto* tree_dock = new QDockWidget("Scene", this);
  tree_dock->setObjectName("Scene");
  tree_dock->setWidget(tree_);
  addDockWidget(Qt::LeftDockWidgetArea, tree_dock);
  properties_ = new PropertyPanel(document_, this);
  QDockWidget* properties_dock = addPanel("Properties", properties_, nullptr);
  // The tree above, the editors tabbed below it.
  splitDockWidget(tree_dock, properties_dock, Qt::Vertical);
  supports_ = new HoldsPanel(HoldsPanel::Role::kSupports, document_, this);
  QDockWidget* supports_dock = addPanel("Supports", supports_, properties_dock);
  grippers_ = new HoldsPanel(HoldsPanel::Role::kGrippers, document_, this);
  QDockWidget* grippers_dock = addPanel("Grippers", grippers_, properties_dock);
  loads_ = new LoadsPanel(document_, this);
  QDockWidget* loads_dock = addPanel("Loads", loads_, properties_dock);
  obstacles_ = new ObstaclesPanel(document_, this);
  QDockWidget* obstacles_dock = addPanel("Obstacles", obstacles_, properties_dock);
  stages_ = new StagesPanel(document_, this);
  QDockWidget* stages_dock = addPanel("Stages", stages_, properties_dock);
  probes_ = new ProbesPanel(document_, this);
  QDockWidget* probes_dock = addPanel("Probes", probes_, properties_dock);
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
  // obstacle's with the obstacles.
  // (A dock tabbed behind another still says isVisible(); the signal says
  // when its tab is selected or unselected.)
  connect(stages_dock, &QDockWidget::visibilityChanged, this, [this](bool shown) {
    stages_shown_ = shown;
    updateHandles();
  });
  connect(obstacles_dock, &QDockWidget::visibilityChanged, this, [this](bool shown) {
    obstacles_shown_ = shown;
    updateHandles();
  });
  plot_ = new RunPlot(this);
  auto* plot_dock = new QDockWidget("Run", this);
  plot_dock->setObjectName("Run");
  plot_dock->setWidget(plot_);
  addDockWidget(Qt::BottomDockWidgetArea, plot_dock);
  probe_plot_ = new ProbePlot(this);
  auto* probe_dock = new QDockWidget("Probe plot", this);
  probe_dock->setObjectName("Probe plot");
  probe_dock->setWidget(probe_plot_);
  addDockWidget(Qt::BottomDockWidgetArea, probe_dock);
  tabifyDockWidget(plot_dock, probe_dock);
  residual_plot_ = new ResidualPlot(this);
  auto* residual_dock = new QDockWidget("Residuals", this);
  residual_dock->setObjectName("Residuals");
  residual_dock->setWidget(residual_plot_);
  addDockWidget(Qt::BottomDockWidgetArea, residual_dock);
  tabifyDockWidget(plot_dock, residual_dock);
  reaction_plot_ = new ReactionPlot(this);
  auto* reaction_dock = new QDockWidget("Reactions", this);
  reaction_dock->setObjectName("Reactions");
  reaction_dock->setWidget(reaction_plot_);
  addDockWidget(Qt::BottomDockWidgetArea, reaction_dock);
  tabifyDockWidget(plot_dock, reaction_dock);
  plot_dock->raise();
  connect(tree_, &ModelTree::chosen, this, [this](ModelTree::Part part, int index, int move) {
    showEditor(static_cast<int>(part), index, move);
  });
  connect(tree_, &ModelTree::opened, this, [this](ModelTree::Part part, int, int) {
    if (part == ModelTree::Part::kMaterial && material_->isEnabled()) material_->trigger();
  });
  connect(document_, &SceneDocument::changed, this, &MainWindow::onDocumentChanged);
  connect(timeline_, &QSlider::valueChanged, this, [this](int i) {
    follow_ = i == stepCount();
    showStep(i);
  });
  handles_ = new PathHandles(viewport_->interactor(), this);
  connect(handles_, &PathHandles::released, this, &MainWindow::onPathDragged);
  connect(handles_, &PathHandles::previewed, this, [this] { viewport_->requestRender(); });
  connect(stages_->moves(), &MoveEditor::moveSelected, this, [this](int stage, int move) {
    handle_stage_ = stage;
    handle_move_ = move;
    updateHandles();
  });
  obstacle_handles_ = new DragHandles(viewport_->interactor(), this);
  connect(obstacle_handles_, &DragHandles::released, this, &MainWindow::onObstacleDragged);
  connect(obstacle_handles_, &DragHandles::dragged, this, [this] { viewport_->requestRender(); });
  connect(obstacles_, &ObstaclesPanel::obstacleSelected, this, [this](int i) {
    handle_obstacle_ = i;
    updateHandles();
  });
  connect(viewport_, &VtkViewport::picked, this, &MainWindow::pickNear);
  // Until the user turns the view, it keeps the whole run framed as the
  // window's layout settles or is resized.
  connect(viewport_, &VtkViewport::cameraTouched, this, [this] { camera_touched_ = true; });
  connect(viewport_, &VtkViewport::resized, this, [this] {
    if (!renderer_ || camera_touched_) return;
    renderer_->FitCamera();
    viewport_->requestRender();
  });
  // The run's error estimate stands at the status bar's right, beside the
  // summary the bar shows when the run is done, and stays there when other
  // messages replace that summary.
  estimate_label_ = new ErrorEstimateLabel(statusBar());
  buildActions();
  updateControls();
  // Seven editors share the left dock area: their tabs stand on its side.
  setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
  resize(1280, 960);
  QSettings settings;
  if (settings.contains("window/geometry"))
    restoreGeometry(settings.value("window/geometry").toByteArray());
  if (settings.contains("window/docks")) restoreState(settings.value("window/docks").toByteArray());
  autosave_timer_ = new QTimer(this);
  autosave_timer_->setInterval(60 * 1000);
  connect(autosave_timer_, &QTimer::timeout, this, &MainWindow::autosave);
  autosave_timer_->start();
}

QDockWidget* MainWindow::addPanel(const QString& title, QWidget* panel, QDockWidget* tab_with) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(title);  // for saveState
  dock->setWidget(panel);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  if (tab_with) tabifyDockWidget(tab_with, dock);
  return dock;
}

// The editor of what the model tree chose, raised, with the item selected.
void MainWindow::showEditor(int part, int index, int move) {
  if (part < 0 || part >= static_cast<int>(editor_docks_.size())) return;
  editor_docks_[part]->raise();
  if (index < 0) return;
  switch (static_cast<ModelTree::Part>(part)) {
    case ModelTree::Part::kSupports:
      supports_->list()->setCurrentRow(index);
      break;
    case ModelTree::Part::kGrippers:
      grippers_->list()->setCurrentRow(index);
      break;
    case ModelTree::Part::kObstacles:
      obstacles_->list()->setCurrentRow(index);
      break;
    case ModelTree::Part::kStages:
      stages_->list()->setCurrentRow(index);
      if (move >= 0) stages_->moves()->list()->setCurrentRow(move);
      break;
    case ModelTree::Part::kProbes:
      probes_->list()->setCurrentRow(index);
      break;
    case ModelTree::Part::kLoads:
      loads_->list()->setCurrentRow(index);
      break;
    default:
      break;
  }
}

QString MainWindow::autosavePath() {
  return SceneKeeper::AutosavePath();
}

bool MainWindow::autosave() {
  if (!model_) return false;
  const KeeperOutcome saved = SceneKeeper::Autosave(*document_);
  if (!saved.done && document_->isModified()) statusBar()->showMessage(saved.message);
  return saved.done;
}

bool MainWindow::recoverAutosave() {
  if (isRunning() || !QFileInfo::exists(autosavePath())) return false;
  const KeeperOutcome recovered = SceneKeeper::Recover(*document_);
  if (recovered.done)
    statusBar()->showMessage(recovered.message);
  else
    ShowError(this, "Cannot recover the autosaved scene", recovered.message);
  return recovered.done;
}

QStringList MainWindow::recentFiles() const {
  return SceneKeeper::RecentFiles();
}

void MainWindow::rememberRecent(const QString& file) {
  SceneKeeper::Remember(file);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recent_menu_->clear();
  for (const QString& file : recentFiles())
    recent_menu_->addAction(QFileInfo(file).fileName(), this, [this, file] { openScene(file); })
        ->setToolTip(file);
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (document_->isModified()) {
    const auto answer =
        QMessageBox::question(this,
                              "Unsaved changes",
                              "Save the changes to the scene before closing?",
                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel || (answer == QMessageBox::Save && !saveScene())) {
      event->ignore();
      return;
    }
  }
  stop();
  QSettings().setValue("window/geometry", saveGeometry());
  QSettings().setValue("window/docks", saveState());
  SceneKeeper::ForgetAutosave();  // a clean close: nothing to recover
  event->accept();
}

MainWindow::~MainWindow() {
  delete runs_;  // stops the run and joins its thread before the window goes
  runs_ = nullptr;
  // The renderer's actors live in the viewport's window: release them while
  // the GL context exists.
  viewport_->makeCurrent();
  handles_->clear();
  obstacle_handles_->clear();
  renderer_.reset();
  viewport_->doneCurrent();
}

void MainWindow::buildActions() {
  QMenu* file = menuBar()->addMenu("&File");
  recent_menu_ = file->addMenu("Open &recent");
  rebuildRecentMenu();
  QMenu* templates = file->addMenu("&New from template");
  const QDir scenes(QString::fromStdString((ResourceDir() / "scenes").string()));
  for (const QString& name : scenes.entryList({"*.json"}, QDir::Files, QDir::Name))
    templates->addAction(QFileInfo(name).completeBaseName(),
                         this,
                         [this, path = scenes.filePath(name)] { newFromTemplate(path); });
  file->addAction("Recover autosaved scene", this, &MainWindow::recoverAutosave);
  QMenu* edit = menuBar()->addMenu("&Edit");
  undo_ = document_->undoStack()->createUndoAction(this, "&Undo");
  undo_->setShortcut(QKeySequence::Undo);
  redo_ = document_->undoStack()->createRedoAction(this, "&Redo");
  redo_->setShortcut(QKeySequence::Redo);
  edit->addAction(undo_);
  edit->addAction(redo_);
  edit->addSeparator();
  material_ = edit->addAction("&Material…", this, [this] {
    auto* dialog = new MaterialDialog(document_, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
  });
  pick_ = edit->addAction("&Pick nodes", this, [this](bool on) {
    viewport_->setPickMode(on);
    statusBar()->showMessage(on ? "pick mode: click the fabric to pick or unpick a node"
                                : QString("%1 nodes picked").arg(picked_.size()));
  });
  pick_->setCheckable(true);
  pick_->setShortcut(Qt::Key_P);
  edit->addAction("&Clear picked nodes", this, &MainWindow::clearPicked);
  QToolBar* bar = addToolBar("Run");
  open_ = bar->addAction("Open…", this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, "Open scene", {}, "Scenes (*.json)");
    if (!file.isEmpty()) openScene(file);
  });
  open_->setShortcut(QKeySequence::Open);
  QAction* save = bar->addAction("Save", this, [this] {
    if (document_->file().isEmpty()) {
      const QString file = QFileDialog::getSaveFileName(this, "Save scene", {}, "Scenes (*.json)");
      if (!file.isEmpty()) saveScene(file);
    } else {
      saveScene();
    }
  });
  save->setShortcut(QKeySequence::Save);
  QAction* save_as = bar->addAction("Save as…", this, [this] {
    const QString file = QFileDialog::getSaveFileName(this, "Save scene as", {}, "Scenes (*.json)");
    if (!file.isEmpty()) saveScene(file);
  });
  save_as->setShortcut(QKeySequence::SaveAs);
  run_ = bar->addAction("Run", this, &MainWindow::run);
  run_->setShortcut(Qt::Key_F5);
  pause_ = bar->addAction("Pause", this, &MainWindow::pauseOrResume);
  pause_->setShortcut(Qt::Key_F6);
  step_ = bar->addAction("Step", this, &MainWindow::stepOnce);
  step_->setShortcut(Qt::Key_F7);
  stop_ = bar->addAction("Stop", this, &MainWindow::stop);
  stop_->setShortcut(Qt::Key_Escape);
  bar->addSeparator();
  QAction* export_image = bar->addAction("Export image…", this, [this] {
    const QString file = QFileDialog::getSaveFileName(this, "Export image", {}, "PNG (*.png)");
    QString error;
    if (!file.isEmpty() && !exportImage(file, &error)) ShowError(this, "Export failed", error);
  });
  export_image->setShortcut(Qt::CTRL | Qt::Key_E);
  QMenu* view = menuBar()->addMenu("&View");
  view->addAction("&Previous step", this, [this] { showStep(currentStep() - 1); })
      ->setShortcut(Qt::ALT | Qt::Key_Left);
  view->addAction("&Next step", this, [this] { showStep(currentStep() + 1); })
      ->setShortcut(Qt::ALT | Qt::Key_Right);
  view->addAction("&Reference state", this, [this] { showStep(0); })
      ->setShortcut(Qt::ALT | Qt::Key_Home);
  view->addAction("&Last step", this, [this] { showStep(stepCount()); })
      ->setShortcut(Qt::ALT | Qt::Key_End);
  view->addAction("P&lay", this, &MainWindow::play)->setShortcut(Qt::CTRL | Qt::Key_Space);
  view->addSeparator();
  // The camera fitted to the run again, from a direction of `drape render`.
  const std::pair<const char*, Qt::Key> cameras[] = {
      {"iso", Qt::Key_1}, {"front", Qt::Key_2}, {"top", Qt::Key_3}, {"side", Qt::Key_4}};
  for (const auto& [name, key] : cameras)
    view->addAction(
            QString("Camera &%1").arg(name),
            this,
            [this, camera = std::string(name)] { setCamera(QString::fromStdString(camera)); })
        ->setShortcut(Qt::CTRL | key);
  QAction* export_vtu = bar->addAction("Export VTU…", this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, "Export the run as VTU into");
    QString error;
    if (!dir.isEmpty() && !exportVtu(dir, &error) && !error.isEmpty())
      ShowError(this, "Export failed", error);
  });
  export_vtu->setToolTip("every step as .vtu with a run.pvd ParaView plays");
  bar->addAction("Export animation…", this, [this] {
    const QString file =
        QFileDialog::getSaveFileName(this, "Export animation", {}, "Movies (*.mp4 *.gif *.ogv)");
    QString error;
    if (!file.isEmpty() && !exportAnimation(file, 25, &error) && !error.isEmpty())
      ShowError(this, "Export failed", error);
  });
}

void MainWindow::updateControls() {
  const bool loaded = model_ != nullptr;
  open_->setEnabled(!isRunning());
  run_->setEnabled(loaded && !isRunning());
  // A run works on the scene it started with: no edits meanwhile.
  properties_->setEnabled(!isRunning());
  stages_->setEnabled(!isRunning());
  supports_->setEnabled(!isRunning());
  grippers_->setEnabled(!isRunning());
  obstacles_->setEnabled(!isRunning());
  loads_->setEnabled(!isRunning());
  probes_->setEnabled(!isRunning());
  material_->setEnabled(!isRunning() && model_ != nullptr);
  undo_->setEnabled(!isRunning() && document_->undoStack()->canUndo());
  redo_->setEnabled(!isRunning() && document_->undoStack()->canRedo());
  pause_->setEnabled(isRunning());
  pause_->setText(isPaused() ? "Resume" : "Pause");
  // One step of the run: the estimate's runs on coarser meshes have none.
  step_->setEnabled(isRunning() && isPaused() && !estimating_);
  stop_->setEnabled(isRunning());
}

bool MainWindow::openScene(const QString& file) {
  if (isRunning()) return false;
  try {
    // Checked whole before the document takes it: a scene that cannot be
    // modelled is refused with the reader's or the engine's message.
    BuildShellModel(ReadScene(file.toStdString()));
    document_->open(file);
  } catch (const std::exception& e) {
    ShowError(this, "Cannot open the scene", QString::fromStdString(e.what()));
    statusBar()->showMessage(QString::fromStdString(e.what()));
    return false;
  }
  setWindowTitle(QFileInfo(file).fileName() + " — Drape Studio");
  rememberRecent(file);
  return model_ != nullptr;
}

bool MainWindow::newFromTemplate(const QString& file) {
  if (isRunning()) return false;
  try {
    BuildShellModel(ReadScene(file.toStdString()));
    document_->openTemplate(file);
  } catch (const std::exception& e) {
    ShowError(this, "Cannot open the template", QString::fromStdString(e.what()));
    return false;
  }
  setWindowTitle("untitled (" + QFileInfo(file).completeBaseName() + ") — Drape Studio");
  return model_ != nullptr;
}

bool MainWindow::saveScene(const QString& file) {
  try {
    document_->saveAs(file.isEmpty() ? document_->file() : file);
    statusBar()->showMessage("saved " + document_->file());
    setWindowTitle(QFileInfo(document_->file()).fileName() + " — Drape Studio");
    return true;
  } catch (const std::exception& e) {
    ShowError(this, "Cannot save the scene", QString::fromStdString(e.what()));
    return false;
  }
}

// The scene changed (opened, edited, undone): a new model and view; the
// steps of an earlier run no longer belong to it. An edit the engine cannot
// model is taken back with its message.
void MainWindow::onDocumentChanged() {
  if (isRunning()) return;  // cannot happen: edits are off during a run
  std::unique_ptr<ShellModel> model;
  try {
    model = std::make_unique<ShellModel>(BuildShellModel(document_->scene()));
  } catch (const std::exception& e) {
    statusBar()->showMessage(QString::fromStdString(e.what()));
    if (document_->undoStack()->canUndo()) {
      ShowError(this, "Edit refused", QString::fromStdString(e.what()));
      QTimer::singleShot(0, this, [this] { document_->undoStack()->undo(); });
    }
    return;
  }
  viewport_->makeCurrent();
  handles_->clear();
  obstacle_handles_->clear();
  renderer_.reset();
  viewport_->doneCurrent();
  scene_ = document_->scene();
  if (model_ && model->NodeCount() != model_->NodeCount()) WarnOfNodeNumbers(scene_);
  if (!model_ || model->NodeCount() != model_->NodeCount()) clearPicked();
  model_ = std::move(model);
  steps_.clear();
  estimate_label_->clear();
  rebuildRenderer();
  timeline_->setRange(0, 0);
  showStep(0);
  statusBar()->showMessage(QString("%1: %2 nodes, %3 elements")
                               .arg(QString::fromStdString(scene_.name))
                               .arg(model_->NodeCount())
                               .arg(model_->mesh.ElementCount()));
  updateControls();
}

// Selections by node number hold on the mesh they were picked on: after
// the mesh changed they may hold other places of the part.
void MainWindow::WarnOfNodeNumbers(const Scene& scene) {
  QStringList names;
  auto check = [&](const std::string& name, const Selection& s) {
    if (std::holds_alternative<NodesSelection>(s.shape)) names << QString::fromStdString(name);
  };
  for (const Support& s : scene.supports) check(s.name, s.select);
  for (const Gripper& g : scene.grippers) check(g.name, g.select);
  for (const PointLoad& l : scene.loads) check(l.name, l.select);
  if (!names.isEmpty())
    ShowError(this,
              "Check the held nodes",
              "The mesh changed; " + names.join(", ") +
                  " hold nodes by their numbers, which are other places on the new mesh. "
                  "Pick them again or hold them by a rule.");
}

void MainWindow::rebuildRenderer() {
  // The camera sees the part and where its grippers will take it.
  Eigen::AlignedBox3d bounds = RunBounds(scene_, {&model_->reference});
  for (const auto& p : GripperPathPoints(scene_, *model_)) bounds.extend(p);
  viewport_->makeCurrent();
  handles_->clear();  // their widgets point at the old renderer
  obstacle_handles_->clear();
  renderer_.reset();  // its actors leave the window before the new ones come
  renderer_ = std::make_unique<FrameRenderer>(
      scene_, *model_, view_, bounds, std::nullopt, viewport_->renderWindow());
  viewport_->doneCurrent();
  camera_touched_ = false;
  updateHandles();
  updateMarkers();
}

// The selected move's path gets handles, unless a run is going on (edits
// wait for it) or the move carries no gripper of the model.
void MainWindow::updateHandles() {
  if (!handles_ || !obstacle_handles_) return;  // still being built
  handles_->clear();
  obstacle_handles_->clear();
  viewport_->requestRender();
  if (isRunning() || !renderer_) return;
  if (stages_shown_) {
    // A gripper's path or an obstacle's: each starts where its carried
    // point is when the stage begins.
    std::vector<CarriedMove> moves = GripperMoves(scene_, *model_);
    for (const CarriedMove& m : ObstacleMoves(scene_)) moves.push_back(m);
    for (const CarriedMove& m : moves)
      if (m.stage == handle_stage_ && m.move == handle_move_)
        handles_->show(renderer_->renderer(), scene_.stages[m.stage].moves[m.move].path, m.start);
  }
  if (obstacles_shown_ && handle_obstacle_ >= 0 &&
      handle_obstacle_ < static_cast<int>(scene_.obstacles.size()))
    if (const auto anchor = ObstacleAnchor(scene_.obstacles[handle_obstacle_]))
      obstacle_handles_->show(renderer_->renderer(), {*anchor});
}

void MainWindow::onObstacleDragged() {
  Scene after = document_->scene();
  if (handle_obstacle_ < 0 || handle_obstacle_ >= static_cast<int>(after.obstacles.size())) return;
  Obstacle& o = after.obstacles[handle_obstacle_];
  const auto anchor = ObstacleAnchor(o);
  if (!anchor) return;
  o = Translated(o, obstacle_handles_->position(0) - *anchor);
  ApplyAfterDrag("move " + QString::fromStdString(o.name), after);
}

// Applied once VTK has finished with the drag's events: the edit remakes
// the renderer the handles live in. A refused edit puts them back.
void MainWindow::ApplyAfterDrag(const QString& what, const Scene& after) {
  QTimer::singleShot(0, this, [this, what, after] {
    QString problem;
    if (!document_->tryApply(what, after, &problem)) {
      statusBar()->showMessage(problem);
      updateHandles();
    }
  });
}

void MainWindow::onPathDragged(const Path& path) {
  Scene after = document_->scene();
  if (handle_stage_ < 0 || handle_stage_ >= static_cast<int>(after.stages.size()) ||
      handle_move_ < 0 ||
      handle_move_ >= static_cast<int>(after.stages[handle_stage_].moves.size()))
    return;
  Move& move = after.stages[handle_stage_].moves[handle_move_];
  move.path = path;
  ApplyAfterDrag("drag the path of " +
                     QString::fromStdString(move.gripper.empty() ? move.obstacle : move.gripper),
                 after);
}

void MainWindow::pickNear(const Eigen::Vector3d& point) {
  if (!model_) return;
  const int i = currentStep();
  const Eigen::MatrixX3d& x = i > 0 ? steps_[i - 1]->state.positions : model_->reference.positions;
  Eigen::Index nearest = 0;
  (x.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  const int node = static_cast<int>(nearest);
  const auto it = std::find(picked_.begin(), picked_.end(), node);
  const bool added = it == picked_.end();
  if (added)
    picked_.push_back(node);
  else
    picked_.erase(it);
  PublishPicked();
  statusBar()->showMessage(QString("node %1 %2; %3 nodes picked")
                               .arg(node)
                               .arg(added ? "picked" : "unpicked")
                               .arg(picked_.size()));
}

void MainWindow::clearPicked() {
  picked_.clear();
  PublishPicked();
}

// The editors that can use picked nodes hear of them, with their reference
// positions; the view marks them.
void MainWindow::PublishPicked() {
  std::vector<std::array<double, 2>> at;
  for (int n : picked_)
    at.push_back({model_->reference.positions(n, 0), model_->reference.positions(n, 1)});
  supports_->setPickedNodes(picked_, at);
  grippers_->setPickedNodes(picked_, at);
  loads_->setPickedNodes(picked_, at);
  probes_->setPicked(at);
  updateMarkers();
}

void MainWindow::updateMarkers() {
  if (!renderer_) return;
  const int i = currentStep();
  const Eigen::MatrixX3d& x = i > 0 ? steps_[i - 1]->state.positions : model_->reference.positions;
  std::vector<Eigen::Vector3d> points;
  for (int node : picked_) points.push_back(x.row(node).transpose());
  viewport_->showMarkers(renderer_->renderer(), points);
}

int MainWindow::currentStep() const {
  return timeline_->value();
}

bool MainWindow::setCamera(const QString& view) {
  if (!QStringList{"iso", "front", "top", "side"}.contains(view)) return false;
  view_.camera = CameraSpec{};
  view_.camera.view = view.toStdString();
  redrawView();
  return true;
}

bool MainWindow::setField(const QString& name) {
  std::optional<FieldKind> kind;
  if (!name.isEmpty()) {
    const auto f = FindField(name.toStdString());
    if (!f) return false;
    kind = f->kind;
  }
  view_.field = kind;
  ShowChoice(field_, name);
  redrawView();
  return true;
}

bool MainWindow::setColourMap(const QString& name) {
  const auto map = ColourMapNamed(name.toStdString());
  if (!map) return false;
  view_.colour_map = *map;
  ShowChoice(colour_map_, name);
  redrawView();
  return true;
}

// The view's look changed: a renderer built with it, on the step shown.
void MainWindow::redrawView() {
  if (!model_) return;
  rebuildRenderer();
  showStep(currentStep());
}

void MainWindow::play() {
  if (stepCount() == 0) return;
  if (currentStep() >= stepCount()) timeline_->setValue(0);
  player_->start();
}

ExportedRun MainWindow::exportedRun() const {
  return {&scene_, model_.get(), &steps_, currentStep(), isRunning()};
}

// The viewport's look at the viewport's size: a picture shows what the
// screen does.
RenderOptions MainWindow::viewportLook() const {
  RenderOptions look = view_;
  look.width = viewport_->width();
  look.height = viewport_->height();
  return look;
}

bool MainWindow::report(const ExportOutcome& outcome, QString* error) {
  if (outcome.written || outcome.cancelled)
    statusBar()->showMessage(outcome.message);
  else if (error)
    *error = outcome.message;
  return outcome.written;
}

bool MainWindow::exportImage(const QString& file, QString* error) {
  if (!model_) return false;
  return report(ExportController(this).Image(exportedRun(), viewportLook(), file), error);
}

bool MainWindow::exportAnimation(const QString& file, double fps, QString* error) {
  return report(ExportController(this).Animation(exportedRun(), viewportLook(), file, fps), error);
}

bool MainWindow::exportVtu(const QString& directory, QString* error) {
  return report(ExportController(this).Vtu(exportedRun(), directory), error);
}

void MainWindow::showStep(int index) {
  if (!renderer_) return;
  index = std::clamp(index, 0, stepCount());
  reaction_plot_->setCurrentStep(index);  // the timeline's index is the step's number
  if (timeline_->value() != index) {
    const QSignalBlocker block(timeline_);
    timeline_->setValue(index);
  }
  Frame frame;
  ShellState reference = model_->reference;
  reference.obstacles.assign(scene_.obstacles.size(), ObstaclePlacement{});
  if (index == 0) {
    frame.state = &reference;
    step_label_->setText("reference state");
  } else {
    const StepState& s = *steps_[index - 1];
    frame.state = &s.state;
    frame.step = s.step;
    frame.stage_name = s.stage_name;
    frame.lambda = s.lambda;
    if (s.contact) frame.contact_pressure = s.contact->pressure;
    step_label_->setText(QString("step %1 of %2 — stage %3, λ = %4")
                             .arg(s.step)
                             .arg(stepCount())
                             .arg(QString::fromStdString(s.stage_name))
                             .arg(s.lambda, 0, 'f', 4));
  }
  try {
    renderer_->Update(frame);
    updateMarkers();
  } catch (const std::invalid_argument& e) {
    // A field this state has no values of (contact pressure of the
    // reference state): say so and keep the picture.
    statusBar()->showMessage(QString::fromStdString(e.what()));
    return;
  }
  viewport_->requestRender();
}

void MainWindow::run() {
  if (!model_ || isRunning()) return;
  steps_.clear();
  plot_->clear();
  probe_plot_->clear();
  residual_plot_->clear();
  reaction_plot_->clear();
  reaction_plot_->setScene(scene_);
  estimating_ = false;
  estimate_label_->clear();
  timeline_->setRange(0, 0);
  follow_ = true;
  handles_->clear();  // no edits while the run goes on
  obstacle_handles_->clear();
  runs_->start(scene_);
  document_->setLocked(true);
  updateControls();
  statusBar()->showMessage("running…");
}

void MainWindow::pauseOrResume() {
  runs_->pauseOrResume();
  updateControls();
}

void MainWindow::stepOnce() {
  runs_->stepOnce();
}

void MainWindow::stop() {
  runs_->stop();
}

// Every step is kept and plotted; the view draws only the newest of the
// steps that arrived together (one draw after the queued ones are taken).
void MainWindow::onStep(std::shared_ptr<const StepState> step) {
  plot_->add(*step);
  probe_plot_->add(*step);
  residual_plot_->add(*step);
  reaction_plot_->add(*step);
  steps_.push_back(std::move(step));
  const QSignalBlocker block(timeline_);
  timeline_->setRange(0, stepCount());
  if (follow_ && !draw_pending_) {
    draw_pending_ = true;
    QTimer::singleShot(0, this, [this] {
      draw_pending_ = false;
      if (!follow_) return;
      const QSignalBlocker block(timeline_);
      timeline_->setValue(stepCount());
      showStep(stepCount());
    });
  }
}

bool MainWindow::isRunning() const {
  return runs_ && runs_->isRunning();
}
bool MainWindow::isPaused() const {
  return runs_ && runs_->isPaused();
}

const std::optional<ErrorEstimate>& MainWindow::errorEstimate() const {
  return estimate_label_->estimate();
}

QLabel* MainWindow::errorEstimateLabel() const {
  return estimate_label_;
}

// The run is complete; the worker solves the scene again on meshes 2h and
// 4h (Stop ends that too).
void MainWindow::onEstimating() {
  estimating_ = true;
  statusBar()->showMessage("estimating the error on meshes 2 and 4 times coarser…");
  estimate_label_->showEstimating();
  updateControls();
}

void MainWindow::onErrorEstimated(const ErrorEstimate& estimate) {
  estimate_label_->showEstimate(estimate);
}

void MainWindow::onFinished(const SolveSummary& summary) {
  if (estimating_ && !estimate_label_->estimate()) estimate_label_->showStopped();
  estimating_ = false;
  document_->setLocked(false);
  statusBar()->showMessage(QString::fromStdString(summary.BriefReport()));
  updateControls();
  updateHandles();
  emit runFinished(summary);
}

void MainWindow::onFailed(const QString& message) {
  ShowError(this, "The run could not start", message);
}

}  // namespace drape
