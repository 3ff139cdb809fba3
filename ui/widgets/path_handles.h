// 3-D handles on one move's path in the viewport: a line's end, an arc's
// centre and end, each keyframe, drawn with the path as the gripper would
// follow it while a drag goes on. The path itself is edited by core's
// MovePathHandle; this class turns drags into the path that results.
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Core>
#include <QObject>

#include "core/model/scene.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindowInteractor;

namespace drape {

class DragHandles;

class PathHandles : public QObject {
  Q_OBJECT
 public:
  explicit PathHandles(vtkRenderWindowInteractor* interactor, QObject* parent = nullptr);
  ~PathHandles() override;

  // Handles for `path`, whose held point starts at `start`, in `renderer`
  // (replacing any shown before).
  void show(vtkRenderer* renderer, const Path& path, const Eigen::Vector3d& start);
  // Takes the handles and the preview out of their renderer.
  void clear();
  int count() const;
  Eigen::Vector3d position(int handle) const;
  // The path as the handles now make it (changes while a drag goes on).
  const Path& path() const { return path_; }

 signals:
  void previewed(const drape::Path& path);  // during a drag
  void released(const drape::Path& path);   // when a drag ends

 private:
  void OnDrag(int handle);
  void UpdatePreview();

  DragHandles* handles_;
  vtkSmartPointer<vtkPolyData> line_;
  vtkSmartPointer<vtkActor> preview_;
  Path path_;
  Path dragged_from_;  // the path when the drag began
  Eigen::Vector3d start_ = Eigen::Vector3d::Zero();
};

}  // namespace drape
