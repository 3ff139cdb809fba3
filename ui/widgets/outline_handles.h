// Handles on a polygon outline's vertices in the viewport, in the fabric's
// flat reference plane, with the outline drawn as it will be while a drag
// goes on. Let go, it says which outline the handles now make; the mesh is
// remade by the edit that outline becomes.
#pragma once

#include <vtkSmartPointer.h>
#include <QObject>

#include <vector>

#include "core/model/scene.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindowInteractor;

namespace drape {

class DragHandles;

class OutlineHandles : public QObject {
  Q_OBJECT
 public:
  explicit OutlineHandles(vtkRenderWindowInteractor* interactor, QObject* parent = nullptr);
  ~OutlineHandles() override;

  // A handle per vertex of `outline` in the plane z = `elevation` in
  // `renderer` (replacing any shown before).
  void show(vtkRenderer* renderer, const PolygonOutline& outline, double elevation);
  void clear();
  int count() const;
  Eigen::Vector3d position(int handle) const;
  // The outline as the handles now make it.
  const PolygonOutline& outline() const { return outline_; }

 signals:
  // A drag let go: vertex `handle` moved.
  void released(int handle, const drape::PolygonOutline& outline);

 private:
  void OnDrag(int handle);
  void UpdatePreview();

  DragHandles* handles_;
  vtkSmartPointer<vtkPolyData> line_;
  vtkSmartPointer<vtkActor> preview_;
  PolygonOutline outline_;
  double elevation_ = 0;
};

}  // namespace drape
