// The workbench's view of its scene: the renderer drawing the accepted
// scene and model into the viewport, the run's steps, and the timeline
// under the view (play, the slider, the step shown, the field and colour
// map choices) and the camera. Parts that draw into the view (handles,
// picked nodes) take its renderer and the state it shows, and hear when
// the renderer is remade.
#pragma once

#include <Eigen/Core>
#include <QObject>

#include <memory>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "core/model/unit_system.h"
#include "core/solve/step_state.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/export_controller.h"

class QComboBox;
class QLabel;
class QSlider;
class QTimer;
class QWidget;

namespace drape {

class VtkViewport;

class ViewController : public QObject {
  Q_OBJECT
 public:
  // The timeline's row is made as a child of `bar_parent` (see bar()).
  ViewController(VtkViewport* viewport, QWidget* bar_parent, QObject* parent = nullptr);

  // The row under the view: play, the timeline, the step's label, the field
  // and the colour map.
  QWidget* bar() const { return bar_; }
  QSlider* timeline() const { return timeline_; }
  QLabel* stepLabel() const { return step_label_; }
  // A Cusick test's drape coefficient and node count for the step shown
  // (hidden for other scenes).
  QLabel* drapeLabel() const { return drape_label_; }

  // A scene and its model to show from the reference state: the steps of
  // an earlier run go, and a renderer is made for them. With `keep_result`
  // (an edit that kept the nodes and the obstacles) the last run's final
  // state stays in view at step 0, marked stale, until the next run
  // (clearSteps) or a scene that cannot take it.
  void setScene(const Scene& scene,
                std::shared_ptr<const ShellModel> model,
                bool keep_result = false);
  const Scene& scene() const { return scene_; }
  const std::shared_ptr<const ShellModel>& model() const { return model_; }
  FrameRenderer* renderer() const { return renderer_.get(); }
  // The renderer's actors leave the viewport's window (before it goes).
  void releaseRenderer();

  // A run's steps: cleared as a run starts, each converged step added;
  // the view follows the newest unless the timeline was moved back.
  void clearSteps();
  void addStep(std::shared_ptr<const StepState> step);
  int stepCount() const { return static_cast<int>(steps_.size()); }
  const StepState& step(int i) const { return *steps_.at(i - 1); }  // 1-based
  int currentStep() const;
  // Node positions of the state shown (the reference at step 0).
  const Eigen::MatrixX3d& shownPositions() const;
  // The run as ExportController takes it.
  ExportedRun exportedRun(bool running) const;
  // The look of the view at the viewport's size: a picture shows what the
  // screen does.
  RenderOptions look() const;

  // A preview's ghost (PreviewController::previewStep): `step` on the
  // draft's `model`, drawn over the view; a burst of steps is drawn once
  // (the newest), and again on every new renderer, until clearGhost() or
  // setScene(). `generation` is the preview's, kept for ghostGeneration().
  void setGhost(int generation,
                std::shared_ptr<const ShellModel> model,
                std::shared_ptr<const StepState> step);
  void clearGhost();
  // The ghost drawn (-1 when none) and its model (the draft's).
  int ghostGeneration() const;
  const std::shared_ptr<const ShellModel>& ghostModel() const { return ghost_model_; }
  // The last run's final state shown at step 0 after an edit (null: none).
  const std::shared_ptr<const StepState>& staleResult() const { return stale_; }

  void showStep(int index);  // 0: the reference state (or the stale result)
  void play();               // through the timeline from the shown step
  bool setField(const QString& name);
  bool setColourMap(const QString& name);
  bool setCamera(const QString& view);
  // The colour bar's title and labels in `system` (RenderOptions::units).
  void setUnitSystem(UnitSystem system);
  UnitSystem unitSystem() const { return view_.units; }

 signals:
  void rendererChanging();  // the renderer is about to go: take out what lives in it
  void rendererChanged();   // a new renderer (after setScene or a new look)
  void stepShown(int index);
  void message(const QString& text);

 private:
  void RebuildRenderer();
  // The drape label for the step just shown (ShowStep).
  void ShowDrape();
  void Redraw();
  void DrawGhost();

  VtkViewport* viewport_;
  Scene scene_;
  std::shared_ptr<const ShellModel> model_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::vector<std::shared_ptr<const StepState>> steps_;
  std::shared_ptr<const StepState> stale_;  // the last run's end, after an edit
  std::shared_ptr<const ShellModel> ghost_model_;
  std::shared_ptr<const StepState> ghost_step_;
  int ghost_generation_ = -1;   // of ghost_step_
  int drawn_generation_ = -1;   // of the ghost on the renderer
  bool ghost_pending_ = false;  // the newest ghost is to be drawn
  RenderOptions view_;
  QWidget* bar_ = nullptr;
  QSlider* timeline_ = nullptr;
  QLabel* step_label_ = nullptr;
  QLabel* drape_label_ = nullptr;
  QComboBox* field_ = nullptr;
  QComboBox* colour_map_ = nullptr;
  QTimer* player_ = nullptr;
  bool follow_ = true;           // the newest step is shown as it comes
  bool draw_pending_ = false;    // the newest step is to be drawn
  bool camera_touched_ = false;  // since the renderer was made
};

}  // namespace drape
