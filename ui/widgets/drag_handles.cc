#include "ui/widgets/drag_handles.h"

#include <vtkCommand.h>
#include <vtkHandleWidget.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereHandleRepresentation.h>

namespace drape {

DragHandles::DragHandles(vtkRenderWindowInteractor* interactor, QObject* parent)
    : QObject(parent), interactor_(interactor) {}

DragHandles::~DragHandles() {
  clear();
}

void DragHandles::clear() {
  for (Handle& h : handles_) {
    h.widget->RemoveAllObservers();
    h.widget->EnabledOff();
    h.widget->SetInteractor(nullptr);
  }
  handles_.clear();
  renderer_ = nullptr;
}

void DragHandles::show(vtkRenderer* renderer,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector3d>& colours) {
  clear();
  renderer_ = renderer;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    const Eigen::Vector3d colour = i < colours.size() ? colours[i] : Eigen::Vector3d(1, 0.55, 0);
    Handle h{vtkSmartPointer<vtkHandleWidget>::New(),
             vtkSmartPointer<vtkSphereHandleRepresentation>::New()};
    h.representation->SetHandleSize(18);  // pixels: the same size at any zoom
    h.representation->GetProperty()->SetColor(colour.x(), colour.y(), colour.z());
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
      h.widget->AddObserver(event, this, &DragHandles::OnInteraction);
    h.widget->EnabledOn();
    handles_.push_back(h);
  }
}

vtkRenderer* DragHandles::renderer() const {
  return renderer_;
}

Eigen::Vector3d DragHandles::position(int handle) const {
  double at[3];
  handles_.at(static_cast<size_t>(handle)).representation->GetWorldPosition(at);
  return {at[0], at[1], at[2]};
}

void DragHandles::setPosition(int handle, const Eigen::Vector3d& p) {
  double at[3] = {p.x(), p.y(), p.z()};
  handles_.at(static_cast<size_t>(handle)).representation->SetWorldPosition(at);
}

void DragHandles::OnInteraction(vtkObject* caller, unsigned long event, void*) {
  for (size_t i = 0; i < handles_.size(); ++i) {
    if (handles_[i].widget.GetPointer() != caller) continue;
    const int handle = static_cast<int>(i);
    if (event == vtkCommand::StartInteractionEvent) emit started(handle);
    if (event == vtkCommand::InteractionEvent) emit dragged(handle);
    if (event == vtkCommand::EndInteractionEvent) emit released(handle);
  }
}

}  // namespace drape
