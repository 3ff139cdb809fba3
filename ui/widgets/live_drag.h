// The workbench's live drag: at the last step of a complete run, each held
// gripper has a handle; while one is dragged the fabric follows it, frame by
// frame, from the run's end (core's GripperDrag on the run's own solver),
// drawn in the view at every frame. Let go, the drag becomes one undoable
// edit — the scene with the gripper carried by the drag's translation after
// its stages (DraggedScene) — and the window solves that scene in full.
#pragma once

#include <Eigen/Core>
#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/model/scene.h"
#include "core/solve/gripper_drag.h"
#include "ui/widgets/meta_types.h"

namespace drape {

class DragHandles;
class FrameRenderer;
class ShellSolver;
class VtkViewport;

class LiveDrag : public QObject {
  Q_OBJECT
 public:
  LiveDrag(VtkViewport* viewport, QObject* parent = nullptr);
  ~LiveDrag() override;

  // A run's solver at the end of `scene` (a run that completed every stage).
  void setSolved(std::shared_ptr<ShellSolver> solver, const Scene& scene);
  // The solver given is for exactly `scene`: its end can be dragged.
  bool canDrag(const Scene& scene) const;

  // A handle per held gripper where the run left it, in `renderer`.
  void show(FrameRenderer* renderer);
  void clear();

  // A path handle's drag: the gripper `name` carried by `offset` from the
  // run's end (where the edited path now ends against where it ended),
  // drawn in `renderer`; the drag begins on the first call.
  void follow(FrameRenderer* renderer, const std::string& name, const Eigen::Vector3d& offset);
  // The drag under way ends (its handle or path let go) without an edit.
  void stop();

  DragHandles* handles() const { return handles_; }
  // The grippers with handles, in the handles' order.
  const std::vector<std::string>& grippers() const { return names_; }
  bool isDragging() const { return drag_ != nullptr; }
  // The last frame of the drag under way (or of the last drag).
  const std::optional<DragFrame>& lastFrame() const { return last_; }
  const ShellState* draggedState() const;

 signals:
  // A frame was computed and drawn.
  void frameShown(const drape::DragFrame& frame);
  // Let go away from where it started: the edit to apply.
  void released(const QString& what, const drape::Scene& dragged);
  void message(const QString& text);

 private:
  void OnStarted(int handle);
  void OnDragged(int handle);
  void OnReleased(int handle);
  // Starts a drag of gripper `name`; false (and a message) when it cannot.
  bool Begin(const std::string& name);
  void ShowFrame(FrameRenderer* renderer, const Eigen::Vector3d& offset);

  VtkViewport* viewport_;
  DragHandles* handles_;
  FrameRenderer* renderer_ = nullptr;
  std::shared_ptr<ShellSolver> solver_;
  Scene solved_;  // the scene the solver solved
  std::vector<std::string> names_;
  std::vector<Eigen::Vector3d> starts_;  // each handle where the run left it
  std::unique_ptr<GripperDrag> drag_;
  int dragged_ = -1;     // the handle being dragged (-1: none, or a path's)
  std::string gripper_;  // the gripper being dragged
  std::optional<DragFrame> last_;
};

}  // namespace drape
