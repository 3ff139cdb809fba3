// The handles in the viewport that edit the scene by dragging: the
// selected move's path (while the stages' editor is up), the selected
// obstacle's place (while the obstacles' editor is up) and a polygon
// outline's vertices (while the properties' editor is up). A drag let go is
// one undoable edit of the document; a refused one puts the handles back.
// Handles live in the view's renderer: they go when it is remade and come
// back on the new one; none while a run works on the scene.
//
// The home of every drag in the view that edits the scene, a gripper's
// live drag at a complete run's last step included: it has the viewport,
// the document and the view (renderer, scene, model, shown state).
#pragma once

#include <QObject>
#include <QString>

#include <functional>
#include <memory>

#include "core/model/scene.h"

namespace drape {

class DragHandles;
class LiveDrag;
class OutlineHandles;
class PathHandles;
class ShellSolver;
class SceneDocument;
class ViewController;
class VtkViewport;

class HandleController : public QObject {
  Q_OBJECT
 public:
  HandleController(VtkViewport* viewport,
                   SceneDocument* document,
                   ViewController* view,
                   QObject* parent = nullptr);

  PathHandles* pathHandles() const { return path_; }
  DragHandles* obstacleHandles() const { return obstacle_; }
  LiveDrag* liveDrag() const { return live_; }
  OutlineHandles* outlineHandles() const { return outline_; }

  // A complete run's solver at the end of `scene`: while the view shows
  // that scene's last step and the grippers' editor is up, each held
  // gripper has a handle that drags the fabric live (live_drag.h).
  void setSolved(std::shared_ptr<ShellSolver> solver, const Scene& scene);

  // What gets handles: the move (stage, move) selected in the stages'
  // editor, the obstacle selected in the obstacles' editor; each while its
  // editor's dock is shown.
  void selectMove(int stage, int move);
  void selectObstacle(int obstacle);
  void setStagesShown(bool shown);
  void setObstaclesShown(bool shown);
  // A polygon outline's vertices get handles while the properties show.
  void setPropertiesShown(bool shown);
  // The grippers' live-drag handles show while their editor's dock does.
  void setGrippersShown(bool shown);
  // Off while a run works on the scene (edits wait for it).
  void setEditable(bool editable);

  // The handles shown again for the selection, on the view's renderer.
  void update();
  // The handles taken out of the view.
  void clear();

 signals:
  void message(const QString& text);  // why a drag's edit was refused
  // A gripper's live drag was let go and applied: the edited scene wants
  // its full solve.
  void gripperDragApplied();

 private:
  void OnPathPreviewed(const Path& path);
  void OnPathDragged(const Path& path);
  void OnObstacleDragged();
  void OnOutlineDragged(int vertex, const PolygonOutline& outline);
  // `applied` runs once the edit is accepted.
  void ApplyAfterDrag(const QString& what,
                      const Scene& after,
                      std::function<void()> applied = nullptr);

  VtkViewport* viewport_;
  SceneDocument* document_;
  ViewController* view_;
  PathHandles* path_ = nullptr;
  DragHandles* obstacle_ = nullptr;
  OutlineHandles* outline_ = nullptr;
  LiveDrag* live_ = nullptr;
  int stage_ = -1, move_ = -1;                           // the move whose path has handles
  int obstacle_index_ = -1;                              // the obstacle with a handle
  bool stages_shown_ = false, obstacles_shown_ = false;  // their docks' tabs are up
  bool grippers_shown_ = false;
  bool properties_shown_ = false;
  bool editable_ = true;
};

}  // namespace drape
