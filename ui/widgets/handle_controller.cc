#include "ui/widgets/handle_controller.h"

#include <QTimer>

#include <vector>

#include "core/fe/path_handles.h"
#include "core/fe/prescribed_motion.h"
#include "core/fe/shell_model.h"
#include "core/model/obstacle_anchor.h"
#include "ui/widgets/drag_handles.h"
#include "ui/widgets/form_placement.h"
#include "ui/widgets/live_drag.h"
#include "ui/widgets/outline_handles.h"
#include "ui/widgets/path_handles.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/view_controller.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// No later stage carries the gripper on: where this move ends, the run ends.
bool IsLastMoveOf(const Scene& scene, const CarriedMove& m) {
  for (size_t s = m.stage + 1; s < scene.stages.size(); ++s)
    for (const Move& later : scene.stages[s].moves)
      if (later.gripper == m.carried) return false;
  return true;
}

}  // namespace

HandleController::HandleController(VtkViewport* viewport,
                                   SceneDocument* document,
                                   ViewController* view,
                                   QObject* parent)
    : QObject(parent), viewport_(viewport), document_(document), view_(view) {
  path_ = new PathHandles(viewport_->interactor(), this);
  connect(path_, &PathHandles::released, this, &HandleController::OnPathDragged);
  connect(path_, &PathHandles::previewed, this, &HandleController::OnPathPreviewed);
  obstacle_ = new DragHandles(viewport_->interactor(), this);
  connect(obstacle_, &DragHandles::released, this, &HandleController::OnObstacleDragged);
  connect(obstacle_, &DragHandles::dragged, this, [this] { viewport_->requestRender(); });
  outline_ = new OutlineHandles(viewport_->interactor(), this);
  connect(outline_, &OutlineHandles::released, this, &HandleController::OnOutlineDragged);
  live_ = new LiveDrag(viewport_, this);
  connect(live_, &LiveDrag::message, this, &HandleController::message);
  connect(live_, &LiveDrag::released, this, [this](const QString& what, const Scene& after) {
    ApplyAfterDrag(what, after, [this] { emit gripperDragApplied(); });
  });
  // The gripper handles are there at the last step only.
  connect(view_, &ViewController::stepShown, this, [this] {
    if (!live_->isDragging()) update();
  });
  // Their widgets point into the renderer: out before it goes, back on the new one.
  connect(view_, &ViewController::rendererChanging, this, &HandleController::clear);
  connect(view_, &ViewController::rendererChanged, this, &HandleController::update);
}

void HandleController::selectMove(int stage, int move) {
  stage_ = stage;
  move_ = move;
  update();
}

void HandleController::selectObstacle(int obstacle) {
  obstacle_index_ = obstacle;
  update();
}

void HandleController::setStagesShown(bool shown) {
  stages_shown_ = shown;
  update();
}

void HandleController::setObstaclesShown(bool shown) {
  obstacles_shown_ = shown;
  update();
}

void HandleController::setPropertiesShown(bool shown) {
  properties_shown_ = shown;
  update();
}

void HandleController::setGrippersShown(bool shown) {
  grippers_shown_ = shown;
  update();
}

void HandleController::setEditable(bool editable) {
  editable_ = editable;
  update();
}

void HandleController::setSolved(std::shared_ptr<ShellSolver> solver, const Scene& scene) {
  live_->setSolved(std::move(solver), scene);
  update();
}

void HandleController::clear() {
  path_->clear();
  obstacle_->clear();
  outline_->clear();
  live_->clear();
}

// The selected move's path gets handles, unless a run is going on or the
// move carries no gripper of the model.
void HandleController::update() {
  clear();
  viewport_->requestRender();
  FrameRenderer* renderer = view_->renderer();
  if (!editable_ || !renderer || !view_->model()) return;
  const Scene& scene = view_->scene();
  if (stages_shown_) {
    // A gripper's path or an obstacle's: each starts where its carried
    // point is when the stage begins.
    std::vector<CarriedMove> moves = GripperMoves(scene, *view_->model());
    for (const CarriedMove& m : ObstacleMoves(scene)) moves.push_back(m);
    for (const CarriedMove& m : moves)
      if (m.stage == stage_ && m.move == move_)
        path_->show(renderer->renderer(), scene.stages[m.stage].moves[m.move].path, m.start);
  }
  if (obstacles_shown_ && obstacle_index_ >= 0 &&
      obstacle_index_ < static_cast<int>(scene.obstacles.size()))
    if (const auto anchor = ObstacleAnchor(scene.obstacles[obstacle_index_]))
      obstacle_->show(renderer->renderer(), {*anchor});
  // A pattern piece's outline is edited in the pattern CAD it came from.
  if (properties_shown_)
    if (const auto* polygon = std::get_if<PolygonOutline>(&scene.fabric.outline))
      outline_->show(renderer->renderer(), *polygon, scene.fabric.elevation);
  if (grippers_shown_ && view_->stepCount() > 0 && view_->currentStep() == view_->stepCount() &&
      live_->canDrag(document_->scene()))
    live_->show(renderer);
}

void HandleController::OnObstacleDragged() {
  Scene after = document_->scene();
  if (obstacle_index_ < 0 || obstacle_index_ >= static_cast<int>(after.obstacles.size())) return;
  Obstacle& o = after.obstacles[obstacle_index_];
  const auto anchor = ObstacleAnchor(o);
  if (!anchor) return;
  o = Translated(o, obstacle_->position(0) - *anchor);
  const QString what = "move " + QString::fromStdString(o.name);
  // A fabric laid on the obstacle stays on it.
  if (const auto& model = document_->model())
    after = FollowingTheForm(
        document_->scene(), after, model->mesh, obstacle_index_, document_->directory());
  ApplyAfterDrag(what, after);
}

// The outline the handles make is the fabric's; the document remeshes it,
// or refuses it (an outline that crosses itself) and the handles go back.
void HandleController::OnOutlineDragged(int vertex, const PolygonOutline& outline) {
  Scene after = document_->scene();
  if (!std::holds_alternative<PolygonOutline>(after.fabric.outline)) return;
  after.fabric.outline = outline;
  ApplyAfterDrag(QString("move outline vertex %1").arg(vertex + 1), after);
}

// While the path of a gripper's last move is dragged at the run's end, the
// fabric follows the gripper to where the path now ends.
void HandleController::OnPathPreviewed(const Path& path) {
  viewport_->requestRender();
  const Scene& scene = document_->scene();
  if (!live_->canDrag(scene) || view_->stepCount() == 0 ||
      view_->currentStep() != view_->stepCount() || !view_->model())
    return;
  for (const CarriedMove& m : GripperMoves(scene, *view_->model()))
    if (m.stage == stage_ && m.move == move_ && IsLastMoveOf(scene, m)) {
      const Path& before = scene.stages[m.stage].moves[m.move].path;
      live_->follow(view_->renderer(),
                    m.carried,
                    MotionAt(path, 1).Apply(m.start) - MotionAt(before, 1).Apply(m.start));
    }
}

void HandleController::OnPathDragged(const Path& path) {
  // A drag the fabric followed live is solved in full when let go.
  const bool followed = live_->isDragging();
  live_->stop();
  Scene after = document_->scene();
  if (stage_ < 0 || stage_ >= static_cast<int>(after.stages.size()) || move_ < 0 ||
      move_ >= static_cast<int>(after.stages[stage_].moves.size()))
    return;
  Move& move = after.stages[stage_].moves[move_];
  move.path = path;
  ApplyAfterDrag("drag the path of " +
                     QString::fromStdString(move.gripper.empty() ? move.obstacle : move.gripper),
                 after,
                 followed ? std::function<void()>([this] { emit gripperDragApplied(); }) : nullptr);
}

// Applied once VTK has finished with the drag's events: the edit remakes
// the renderer the handles live in. A refused edit puts them back.
void HandleController::ApplyAfterDrag(const QString& what,
                                      const Scene& after,
                                      std::function<void()> applied) {
  QTimer::singleShot(0, this, [this, what, after, applied] {
    QString problem;
    if (!document_->tryApply(what, after, &problem)) {
      emit message(problem);
      update();
    } else if (applied) {
      applied();
    }
  });
}

}  // namespace drape
