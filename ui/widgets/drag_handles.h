// Spheres in the viewport a user drags with the mouse: VTK handle widgets
// that take the mouse before the camera's trackball, a constant size on
// screen. Says which handle moved, while dragging and when let go; what a
// handle means is up to its owner (a path's end, an obstacle's place).
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Core>
#include <QObject>

#include <vector>

class vtkHandleWidget;
class vtkObject;
class vtkRenderer;
class vtkRenderWindowInteractor;
class vtkSphereHandleRepresentation;

namespace drape {

class DragHandles : public QObject {
  Q_OBJECT
 public:
  explicit DragHandles(vtkRenderWindowInteractor* interactor, QObject* parent = nullptr);
  ~DragHandles() override;

  // One handle per point in `renderer` (replacing any shown before), in
  // the colour of the same index (RGB in [0, 1]; orange when not given).
  void show(vtkRenderer* renderer,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<Eigen::Vector3d>& colours = {});
  void clear();
  int count() const { return static_cast<int>(handles_.size()); }
  vtkRenderer* renderer() const;
  Eigen::Vector3d position(int handle) const;
  void setPosition(int handle, const Eigen::Vector3d& at);

 signals:
  void started(int handle);
  void dragged(int handle);
  void released(int handle);

 private:
  void OnInteraction(vtkObject* caller, unsigned long event, void* data);

  struct Handle {
    vtkSmartPointer<vtkHandleWidget> widget;
    vtkSmartPointer<vtkSphereHandleRepresentation> representation;
  };
  vtkRenderWindowInteractor* interactor_;
  vtkSmartPointer<vtkRenderer> renderer_;  // kept: renderers are remade on edits
  std::vector<Handle> handles_;
};

}  // namespace drape
