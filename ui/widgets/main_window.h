// The workbench's main window: a scene, its 3-D view, a run on a worker
// thread streaming each converged step to the view, and a timeline over the
// steps. (Editors, plots and export come on top of this.)
#pragma once

#include <QMainWindow>

#include <memory>
#include <optional>
#include <vector>

#include "core/model/scene.h"
#include "core/solve/error_estimate.h"
#include "core/solve/shell_model.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/export_controller.h"
#include "ui/widgets/meta_types.h"

class QAction;
class QCloseEvent;
class QDockWidget;
class QMenu;
class QComboBox;
class QLabel;
class QSlider;
class QTimer;

namespace drape {

class ErrorEstimateLabel;
class RunController;

class DragHandles;
class HoldsPanel;
class LoadsPanel;
class ModelTree;
class ObstaclesPanel;
class PathHandles;
class ProbePlot;
class ProbesPanel;
class ReactionPlot;
class ResidualPlot;
class PropertyPanel;
class RunPlot;
class StagesPanel;
class SceneDocument;
class VtkViewport;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Loads a scene file; on error shows the message and keeps what was open.
  bool openScene(const QString& file);
  VtkViewport* viewport() const { return viewport_; }
  SceneDocument* document() const { return document_; }
  PropertyPanel* properties() const { return properties_; }
  RunPlot* plot() const { return plot_; }
  StagesPanel* stages() const { return stages_; }
  HoldsPanel* supports() const { return supports_; }
  HoldsPanel* grippers() const { return grippers_; }
  ObstaclesPanel* obstacles() const { return obstacles_; }
  LoadsPanel* loads() const { return loads_; }
  ProbesPanel* probes() const { return probes_; }
  ModelTree* tree() const { return tree_; }
  ProbePlot* probePlot() const { return probe_plot_; }
  ResidualPlot* residualPlot() const { return residual_plot_; }
  ReactionPlot* reactionPlot() const { return reaction_plot_; }
  PathHandles* pathHandles() const { return handles_; }
  DragHandles* obstacleHandles() const { return obstacle_handles_; }
  // Nodes picked in the viewport (pick mode), in the order picked.
  const std::vector<int>& pickedNodes() const { return picked_; }
  // A new unsaved scene from a template (resources/scenes/*.json).
  bool newFromTemplate(const QString& file);
  // Saves the scene (to `file`, or where it came from); false with a message.
  bool saveScene(const QString& file = {});

  // Autosave: the edited scene is written every minute to autosavePath();
  // a clean close removes it, so one found at start is a crash's.
  static QString autosavePath();
  bool autosave();
  // Opens the autosaved scene (its edits become unsaved changes again).
  bool recoverAutosave();
  QStringList recentFiles() const;
  int stepCount() const { return static_cast<int>(steps_.size()); }
  // Step `i` (1-based, as the timeline counts).
  const StepState& step(int i) const { return *steps_.at(i - 1); }
  int currentStep() const;
  bool isRunning() const;
  bool isPaused() const;
  // The last run's error estimate (solver.error_estimate), shown beside its
  // summary in the status bar: Describe()'s line, the per-probe errors in
  // its tooltip. Empty before the run's estimate came, or without one.
  const std::optional<ErrorEstimate>& errorEstimate() const;
  QLabel* errorEstimateLabel() const;

  // The colour field ("" for none, else a name of Fields()).
  bool setField(const QString& name);
  // Its colours: "viridis" (the default) or "rainbow".
  bool setColourMap(const QString& name);
  // The camera fitted to the run from "iso", "front", "top" or "side" (as
  // `drape render --camera`); also how to get the view back after turning it.
  bool setCamera(const QString& view);
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
  void pauseOrResume();
  void stepOnce();
  void stop();
  void showStep(int index);  // 0: the reference state
  void play();               // through the timeline from the shown step
  // The node nearest `point` in the shown state is picked, or unpicked
  // when it was.
  void pickNear(const Eigen::Vector3d& point);
  void clearPicked();

 signals:
  void runFinished(const drape::SolveSummary& summary);

 private slots:
  void onStep(std::shared_ptr<const drape::StepState> step);
  void onEstimating();
  void onErrorEstimated(const drape::ErrorEstimate& estimate);
  void onFinished(const drape::SolveSummary& summary);
  void onFailed(const QString& message);

 private:
  void buildActions();
  void rememberRecent(const QString& file);
  void rebuildRecentMenu();
  void closeEvent(QCloseEvent* event) override;
  void onDocumentChanged();
  void rebuildRenderer();
  void updateControls();
  void updateHandles();
  void WarnOfNodeNumbers(const Scene& scene);
  ExportedRun exportedRun() const;
  void redrawView();
  RenderOptions viewportLook() const;
  // A written (or cancelled) export in the status bar; otherwise its reason in `error`.
  bool report(const ExportOutcome& outcome, QString* error);
  void updateMarkers();
  void PublishPicked();
  void onPathDragged(const Path& path);
  void onObstacleDragged();
  void ApplyAfterDrag(const QString& what, const Scene& after);
  void showEditor(int part, int index, int move);
  QDockWidget* addPanel(const QString& title, QWidget* panel, QDockWidget* tab_with);

  Scene scene_;
  std::unique_ptr<ShellModel> model_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::vector<std::shared_ptr<const StepState>> steps_;
  VtkViewport* viewport_ = nullptr;
  SceneDocument* document_ = nullptr;
  PropertyPanel* properties_ = nullptr;
  RunPlot* plot_ = nullptr;
  StagesPanel* stages_ = nullptr;
  HoldsPanel *supports_ = nullptr, *grippers_ = nullptr;
  ObstaclesPanel* obstacles_ = nullptr;
  LoadsPanel* loads_ = nullptr;
  ProbesPanel* probes_ = nullptr;
  ModelTree* tree_ = nullptr;
  ProbePlot* probe_plot_ = nullptr;
  ResidualPlot* residual_plot_ = nullptr;
  ReactionPlot* reaction_plot_ = nullptr;
  std::vector<QDockWidget*> editor_docks_;               // by ModelTree::Part
  bool stages_shown_ = false, obstacles_shown_ = false;  // their docks' tabs are up
  PathHandles* handles_ = nullptr;
  DragHandles* obstacle_handles_ = nullptr;
  int handle_obstacle_ = -1;                  // the obstacle with a handle
  int handle_stage_ = -1, handle_move_ = -1;  // the move whose path has handles
  std::vector<int> picked_;
  QSlider* timeline_ = nullptr;
  QComboBox* field_ = nullptr;
  QComboBox* colour_map_ = nullptr;
  QTimer* player_ = nullptr;
  QTimer* autosave_timer_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  RenderOptions view_;
  QLabel* step_label_ = nullptr;
  ErrorEstimateLabel* estimate_label_ = nullptr;  // in the status bar, beside the run's summary
  bool estimating_ = false;  // the run is done; its error estimate is under way
  QAction *undo_ = nullptr, *redo_ = nullptr, *material_ = nullptr, *pick_ = nullptr;
  QAction *open_ = nullptr, *run_ = nullptr, *pause_ = nullptr, *step_ = nullptr, *stop_ = nullptr;
  RunController* runs_ = nullptr;  // the solver's thread while a run goes on
  bool follow_ = true;
  bool draw_pending_ = false;    // the newest step is to be drawn
  bool camera_touched_ = false;  // since the renderer was made
};

}  // namespace drape
