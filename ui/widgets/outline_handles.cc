#include "ui/widgets/outline_handles.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "ui/widgets/drag_handles.h"

#include <cmath>

namespace drape {

OutlineHandles::OutlineHandles(vtkRenderWindowInteractor* interactor, QObject* parent)
    : QObject(parent), handles_(new DragHandles(interactor, this)) {
  line_ = vtkSmartPointer<vtkPolyData>::New();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(line_);
  preview_ = vtkSmartPointer<vtkActor>::New();
  preview_->SetMapper(mapper);
  preview_->GetProperty()->SetColor(0.15, 0.45, 0.95);
  preview_->GetProperty()->SetLineWidth(3.0);
  preview_->PickableOff();
  connect(handles_, &DragHandles::dragged, this, &OutlineHandles::OnDrag);
  connect(handles_, &DragHandles::released, this, [this](int handle) {
    OnDrag(handle);
    emit released(handle, outline_);
  });
}

OutlineHandles::~OutlineHandles() {
  clear();
}

void OutlineHandles::clear() {
  if (handles_->renderer()) handles_->renderer()->RemoveActor(preview_);
  handles_->clear();
}

int OutlineHandles::count() const {
  return handles_->count();
}

Eigen::Vector3d OutlineHandles::position(int handle) const {
  return handles_->position(handle);
}

void OutlineHandles::show(vtkRenderer* renderer, const PolygonOutline& outline, double elevation) {
  clear();
  outline_ = outline;
  elevation_ = elevation;
  std::vector<Eigen::Vector3d> points;
  for (const Vec2& v : outline.vertices) points.emplace_back(v[0], v[1], elevation);
  handles_->show(renderer, points, std::vector<Eigen::Vector3d>(points.size(), {0.15, 0.45, 0.95}));
  renderer->AddActor(preview_);
  UpdatePreview();
}

// A vertex stays in the flat part's plane. The handle moves in a plane
// facing the camera; the vertex goes where the line of sight through it
// meets the part's plane, under the mouse.
void OutlineHandles::OnDrag(int handle) {
  Eigen::Vector3d at = handles_->position(handle);
  if (vtkCamera* camera =
          handles_->renderer() ? handles_->renderer()->GetActiveCamera() : nullptr) {
    double d[3];
    if (camera->GetParallelProjection()) {
      camera->GetDirectionOfProjection(d);
    } else {
      camera->GetPosition(d);
      for (int k = 0; k < 3; ++k) d[k] = at[k] - d[k];
    }
    const Eigen::Vector3d sight(d[0], d[1], d[2]);
    // Seen edge-on the plane gives no point: keep x and y.
    if (std::abs(sight.z()) > 1e-3 * sight.norm()) at += (elevation_ - at.z()) / sight.z() * sight;
  }
  at.z() = elevation_;
  handles_->setPosition(handle, at);
  outline_.vertices.at(static_cast<std::size_t>(handle)) = {at.x(), at.y()};
  UpdatePreview();
}

void OutlineHandles::UpdatePreview() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  const auto& v = outline_.vertices;
  lines->InsertNextCell(static_cast<vtkIdType>(v.size() + 1));
  for (std::size_t i = 0; i <= v.size(); ++i) {
    const Vec2& p = v[i % v.size()];
    lines->InsertCellPoint(points->InsertNextPoint(p[0], p[1], elevation_));
  }
  line_->SetPoints(points);
  line_->SetLines(lines);
  line_->Modified();
}

}  // namespace drape
