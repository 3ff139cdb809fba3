#include "ui/widgets/path_handles.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkHandleWidget.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereHandleRepresentation.h>

#include "core/solve/path_handles.h"

namespace drape {

PathHandles::PathHandles(vtkRenderWindowInteractor* interactor, QObject* parent)
    : QObject(parent), interactor_(interactor) {
  line_ = vtkSmartPointer<vtkPolyData>::New();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(line_);
  preview_ = vtkSmartPointer<vtkActor>::New();
  preview_->SetMapper(mapper);
  preview_->GetProperty()->SetColor(1.0, 0.55, 0.0);
  preview_->GetProperty()->SetLineWidth(3.0);
  preview_->PickableOff();
}

PathHandles::~PathHandles() {
  clear();
}

void PathHandles::clear() {
  for (Handle& h : handles_) {
    h.widget->RemoveAllObservers();
    h.widget->EnabledOff();
    h.widget->SetInteractor(nullptr);
  }
  handles_.clear();
  if (renderer_) renderer_->RemoveActor(preview_);
  renderer_ = nullptr;
}

void PathHandles::show(vtkRenderer* renderer, const Path& path, const Eigen::Vector3d& start) {
  clear();
  renderer_ = renderer;
  path_ = dragged_from_ = path;
  start_ = start;
  for (const Eigen::Vector3d& p : PathHandlePoints(path, start)) {
    Handle h{vtkSmartPointer<vtkHandleWidget>::New(),
             vtkSmartPointer<vtkSphereHandleRepresentation>::New()};
    h.representation->SetHandleSize(18);  // pixels: the same size at any zoom
    h.representation->GetProperty()->SetColor(1.0, 0.55, 0.0);
    h.representation->GetSelectedProperty()->SetColor(1.0, 0.9, 0.2);
    double at[3] = {p.x(), p.y(), p.z()};
    h.representation->SetWorldPosition(at);
    h.widget->SetInteractor(interactor_);
    h.widget->SetRepresentation(h.representation);
    h.widget->SetCurrentRenderer(renderer);
    h.widget->SetPriority(1.0);  // before the camera's trackball
    for (unsigned long event : {vtkCommand::StartInteractionEvent,
                                vtkCommand::InteractionEvent,
                                vtkCommand::EndInteractionEvent})
      h.widget->AddObserver(event, this, &PathHandles::OnInteraction);
    h.widget->EnabledOn();
    handles_.push_back(h);
  }
  renderer_->AddActor(preview_);
  UpdatePreview();
}

Eigen::Vector3d PathHandles::position(int handle) const {
  double at[3];
  handles_.at(static_cast<size_t>(handle)).representation->GetWorldPosition(at);
  return {at[0], at[1], at[2]};
}

void PathHandles::OnInteraction(vtkObject* caller, unsigned long event, void*) {
  int dragged = -1;
  for (size_t i = 0; i < handles_.size(); ++i)
    if (handles_[i].widget.GetPointer() == caller) dragged = static_cast<int>(i);
  if (dragged < 0) return;
  if (event == vtkCommand::StartInteractionEvent) {
    dragged_from_ = path_;
    return;
  }
  path_ = MovePathHandle(dragged_from_, start_, dragged, position(dragged));
  // The other handles follow the path (an arc's end goes round a moved centre).
  const auto points = PathHandlePoints(path_, start_);
  for (size_t i = 0; i < handles_.size(); ++i) {
    if (static_cast<int>(i) == dragged) continue;
    double at[3] = {points[i].x(), points[i].y(), points[i].z()};
    handles_[i].representation->SetWorldPosition(at);
  }
  UpdatePreview();
  if (event == vtkCommand::InteractionEvent) emit previewed(path_);
  if (event == vtkCommand::EndInteractionEvent) emit released(path_);
}

void PathHandles::UpdatePreview() {
  const auto samples = SamplePath(path_, start_);
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->InsertNextCell(static_cast<vtkIdType>(samples.size()));
  for (const Eigen::Vector3d& p : samples)
    lines->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
  line_->SetPoints(points);
  line_->SetLines(lines);
  line_->Modified();
}

}  // namespace drape
