// The workbench's main window: the wiring of its parts. A scene document
// (DocumentController: open, save, autosave; each change modelled once),
// its 3-D view and timeline (ViewController), picking (PickingController)
// and drag handles (HandleController) in the view, a run on a worker thread
// with its plots (RunMonitor), the editors and plots docked (EditorDocks), the menus
// and toolbar (WorkbenchActions), export (ExportController), the unit
// system everything is shown in (UnitSettings, the Units menu) and a draft
// preview of each edit drawn as a ghost (PreviewController).
#pragma once

#include <QMainWindow>

#include <memory>
#include <optional>
#include <vector>

#include "core/model/unit_system.h"
#include "core/solve/error_estimate.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/document_controller.h"
#include "ui/widgets/editor_docks.h"
#include "ui/widgets/error_estimate_label.h"
#include "ui/widgets/export_controller.h"
#include "ui/widgets/handle_controller.h"
#include "ui/widgets/meta_types.h"
#include "ui/widgets/picking_controller.h"
#include "ui/widgets/run_monitor.h"
#include "ui/widgets/scene_keeper.h"
#include "ui/widgets/view_controller.h"

class QCloseEvent;
class QLabel;

namespace drape {

class DragHandles;
class HoldsPanel;
class LoadsPanel;
class PreviewController;
class ModelTree;
class ObstaclesPanel;
class OutlineHandles;
class PathHandles;
class ProbePlot;
class ProbesPanel;
class PropertyPanel;
class ReactionPlot;
class ResidualPlot;
class RunPlot;
class SceneDocument;
class StagesPanel;
class UnitSettings;
class VtkViewport;
class WorkbenchActions;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Loads a scene file; on error shows the message and keeps what was open.
  bool openScene(const QString& file) { return documents_->open(file); }
  // A new unsaved scene from a template (resources/scenes/*.json).
  bool newFromTemplate(const QString& file) { return documents_->newFromTemplate(file); }
  // Saves the scene (to `file`, or where it came from); false with a message.
  bool saveScene(const QString& file = {}) { return documents_->save(file); }
  // Autosave: the edited scene is written every minute to autosavePath();
  // a clean close removes it, so one found at start is a crash's.
  static QString autosavePath() { return SceneKeeper::AutosavePath(); }
  bool autosave() { return documents_->autosave(); }
  // Opens the autosaved scene (its edits become unsaved changes again).
  bool recoverAutosave() { return documents_->recoverAutosave(); }
  QStringList recentFiles() const { return documents_->recentFiles(); }

  // The parts.
  SceneDocument* document() const { return document_; }
  DocumentController* documentController() const { return documents_; }
  VtkViewport* viewport() const { return viewport_; }
  ViewController* view() const { return view_; }
  PickingController* picking() const { return picking_; }
  HandleController* handles() const { return handles_; }
  RunMonitor* runMonitor() const { return monitor_; }
  WorkbenchActions* actions() const { return actions_; }
  UnitSettings* units() const { return units_; }
  PreviewController* previews() const { return previews_; }
  EditorDocks* docks() const { return docks_; }
  PropertyPanel* properties() const { return docks_->properties(); }
  StagesPanel* stages() const { return docks_->stages(); }
  HoldsPanel* supports() const { return docks_->supports(); }
  HoldsPanel* grippers() const { return docks_->grippers(); }
  ObstaclesPanel* obstacles() const { return docks_->obstacles(); }
  LoadsPanel* loads() const { return docks_->loads(); }
  ProbesPanel* probes() const { return docks_->probes(); }
  ModelTree* tree() const { return docks_->tree(); }
  RunPlot* plot() const { return monitor_->plot(); }
  ProbePlot* probePlot() const { return monitor_->probePlot(); }
  ResidualPlot* residualPlot() const { return monitor_->residualPlot(); }
  ReactionPlot* reactionPlot() const { return monitor_->reactionPlot(); }
  PathHandles* pathHandles() const { return handles_->pathHandles(); }
  DragHandles* obstacleHandles() const { return handles_->obstacleHandles(); }
  OutlineHandles* outlineHandles() const { return handles_->outlineHandles(); }
  // Nodes picked in the viewport (pick mode), in the order picked.
  const std::vector<int>& pickedNodes() const { return picking_->picked(); }

  int stepCount() const { return view_->stepCount(); }
  // Step `i` (1-based, as the timeline counts).
  const StepState& step(int i) const { return view_->step(i); }
  int currentStep() const { return view_->currentStep(); }
  bool isRunning() const { return monitor_ && monitor_->isRunning(); }
  bool isPaused() const { return monitor_ && monitor_->isPaused(); }
  // The last run's error estimate (solver.error_estimate), shown beside its
  // summary in the status bar: Describe()'s line, the per-probe errors in
  // its tooltip. Empty before the run's estimate came, or without one.
  const std::optional<ErrorEstimate>& errorEstimate() const {
    return monitor_->estimateLabel()->estimate();
  }
  QLabel* errorEstimateLabel() const { return monitor_->estimateLabel(); }

  // The colour field ("" for none, else a name of Fields()).
  bool setField(const QString& name) { return view_->setField(name); }
  // Its colours: "viridis" (the default) or "rainbow".
  bool setColourMap(const QString& name) { return view_->setColourMap(name); }
  // The camera fitted to the run from "iso", "front", "top" or "side" (as
  // `drape render --camera`); also how to get the view back after turning it.
  bool setCamera(const QString& view) { return view_->setCamera(view); }
  // The shown step as a PNG of the view's size, drawn by the offscreen
  // renderer (the same builder); false with a message on failure.
  bool exportImage(const QString& file, QString* error = nullptr);
  // The run as a movie or frame folder (the same code as `drape animate`),
  // with a progress dialog that can cancel; false when cancelled or failed.
  bool exportAnimation(const QString& file, double fps = 25, QString* error = nullptr);
  // Every state of the run (the reference first) as VTU files with a
  // run.pvd collection in `directory` (the same code as `drape export`),
  // with a progress dialog that can cancel (keeping the steps written).
  bool exportVtu(const QString& directory, QString* error = nullptr);

 public slots:
  void run();
  void pauseOrResume() { monitor_->pauseOrResume(); }
  void stepOnce() { monitor_->stepOnce(); }
  void stop() {
    if (monitor_) monitor_->stop();
  }
  void showStep(int index) { view_->showStep(index); }  // 0: the reference state
  void play() { view_->play(); }                        // through the timeline from the shown step
  // The node nearest `point` in the shown state is picked, or unpicked
  // when it was.
  void pickNear(const Eigen::Vector3d& point) { picking_->pickNear(point); }
  void clearPicked() { picking_->clear(); }

 signals:
  void runFinished(const drape::SolveSummary& summary);

 private:
  void closeEvent(QCloseEvent* event) override;
  void OnAccepted(bool renumbered, bool edited);
  void ShowUnits(UnitSystem system);
  void OnFinished(const SolveSummary& summary);
  void UpdateControls();
  // A written (or cancelled) export in the status bar; otherwise its reason in `error`.
  bool Report(const ExportOutcome& outcome, QString* error);

  SceneDocument* document_ = nullptr;
  DocumentController* documents_ = nullptr;
  VtkViewport* viewport_ = nullptr;
  ViewController* view_ = nullptr;
  PickingController* picking_ = nullptr;
  HandleController* handles_ = nullptr;
  RunMonitor* monitor_ = nullptr;
  WorkbenchActions* actions_ = nullptr;
  UnitSettings* units_ = nullptr;
  PreviewController* previews_ = nullptr;
  EditorDocks* docks_ = nullptr;
};

}  // namespace drape
