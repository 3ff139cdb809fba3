#include "ui/widgets/live_drag.h"

#include <stdexcept>

#include "core/solve/shell_solver.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// Green: a handle that moves the fabric, not the scene's geometry.
const Eigen::Vector3d kGripperColour(0.2, 0.75, 0.35);

// The grippers a scene's stages never release: those still held at its end.
std::vector<std::string> HeldAtTheEnd(const Scene& scene) {
  std::vector<std::string> held;
  for (const Gripper& g : scene.grippers) {
    bool released = false;
    for (const Stage& s : scene.stages)
      for (const std::string& name : s.release) released |= name == g.name;
    if (!released) held.push_back(g.name);
  }
  return held;
}

QString Offset(const Eigen::Vector3d& by) {
  return QString("(%1, %2, %3) cm")
      .arg(100 * by.x(), 0, 'g', 3)
      .arg(100 * by.y(), 0, 'g', 3)
      .arg(100 * by.z(), 0, 'g', 3);
}

}  // namespace

LiveDrag::LiveDrag(VtkViewport* viewport, QObject* parent)
    : QObject(parent),
      viewport_(viewport),
      handles_(new DragHandles(viewport->interactor(), this)) {
  connect(handles_, &DragHandles::started, this, &LiveDrag::OnStarted);
  connect(handles_, &DragHandles::dragged, this, &LiveDrag::OnDragged);
  connect(handles_, &DragHandles::released, this, &LiveDrag::OnReleased);
}

LiveDrag::~LiveDrag() = default;

void LiveDrag::setSolved(std::shared_ptr<ShellSolver> solver, const Scene& scene) {
  drag_.reset();
  solver_ = std::move(solver);
  solved_ = scene;
}

bool LiveDrag::canDrag(const Scene& scene) const {
  return solver_ && solved_ == scene;
}

const ShellState* LiveDrag::draggedState() const {
  return drag_ ? &drag_->state() : nullptr;
}

void LiveDrag::show(FrameRenderer* renderer) {
  clear();
  renderer_ = renderer;
  if (!renderer || !solver_) return;
  names_ = HeldAtTheEnd(solved_);
  starts_.clear();
  for (const std::string& name : names_)
    for (const HeldNodes& g : solver_->model().grippers)
      if (g.name == name) {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int node : g.nodes) centre += solver_->state().positions.row(node).transpose();
        starts_.push_back(centre / static_cast<double>(g.nodes.size()));
      }
  handles_->show(
      renderer->renderer(), starts_, std::vector<Eigen::Vector3d>(starts_.size(), kGripperColour));
}

void LiveDrag::clear() {
  handles_->clear();
  names_.clear();
  starts_.clear();
  renderer_ = nullptr;
}

bool LiveDrag::Begin(const std::string& name) {
  if (!solver_) return false;
  try {
    DragSettings settings;
    settings.threads = 1;  // the GUI thread's frames: see DragSettings::threads
    drag_ = std::make_unique<GripperDrag>(solver_->BasisForDrag(name), settings);
    gripper_ = name;
    last_.reset();
    return true;
  } catch (const std::invalid_argument& e) {
    emit message(QString("cannot drag '%1': %2").arg(QString::fromStdString(name), e.what()));
    return false;
  }
}

void LiveDrag::ShowFrame(FrameRenderer* renderer, const Eigen::Vector3d& offset) {
  last_ = drag_->MoveTo(offset);
  if (renderer) {
    Frame frame;
    frame.state = &drag_->state();
    frame.stage_name = "drag " + gripper_;
    frame.lambda = 1;
    renderer->Update(frame);
    viewport_->requestRender();
  }
  if (last_->snapped)
    emit message(
        QString("'%1' was dragged past where the fabric can follow: it snapped to a stable "
                "rest state, releasing %2 J")
            .arg(QString::fromStdString(gripper_))
            .arg(last_->energy_released, 0, 'g', 3));
  emit frameShown(*last_);
}

void LiveDrag::OnStarted(int handle) {
  if (handle < 0 || handle >= static_cast<int>(names_.size())) return;
  if (Begin(names_[handle])) dragged_ = handle;
}

void LiveDrag::OnDragged(int handle) {
  if (drag_ && handle == dragged_)
    ShowFrame(renderer_, handles_->position(handle) - starts_[handle]);
}

void LiveDrag::follow(FrameRenderer* renderer,
                      const std::string& name,
                      const Eigen::Vector3d& offset) {
  if ((!drag_ || gripper_ != name) && !Begin(name)) return;
  dragged_ = -1;
  ShowFrame(renderer, offset);
}

void LiveDrag::stop() {
  drag_.reset();
  dragged_ = -1;
}

void LiveDrag::OnReleased(int handle) {
  if (!drag_ || handle != dragged_) return;
  const Eigen::Vector3d by = handles_->position(handle) - starts_[handle];
  const std::string name = names_[handle];
  stop();
  // A click without a drag is no edit.
  if (by.norm() <= 1e-9 * solver_->model().characteristic_length) return;
  emit released(QString("drag %1 by %2").arg(QString::fromStdString(name), Offset(by)),
                DraggedScene(solved_, name, by));
}

}  // namespace drape
