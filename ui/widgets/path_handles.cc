#include "ui/widgets/path_handles.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "core/fe/path_handles.h"
#include "ui/widgets/drag_handles.h"

namespace drape {

PathHandles::PathHandles(vtkRenderWindowInteractor* interactor, QObject* parent)
    : QObject(parent), handles_(new DragHandles(interactor, this)) {
  line_ = vtkSmartPointer<vtkPolyData>::New();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(line_);
  preview_ = vtkSmartPointer<vtkActor>::New();
  preview_->SetMapper(mapper);
  preview_->GetProperty()->SetColor(1.0, 0.55, 0.0);
  preview_->GetProperty()->SetLineWidth(3.0);
  preview_->PickableOff();
  connect(handles_, &DragHandles::started, this, [this] { dragged_from_ = path_; });
  connect(handles_, &DragHandles::dragged, this, [this](int handle) {
    OnDrag(handle);
    emit previewed(path_);
  });
  connect(handles_, &DragHandles::released, this, [this](int handle) {
    OnDrag(handle);
    emit released(path_);
  });
}

PathHandles::~PathHandles() {
  clear();
}

void PathHandles::clear() {
  if (handles_->renderer()) handles_->renderer()->RemoveActor(preview_);
  handles_->clear();
}

int PathHandles::count() const {
  return handles_->count();
}

Eigen::Vector3d PathHandles::position(int handle) const {
  return handles_->position(handle);
}

void PathHandles::show(vtkRenderer* renderer, const Path& path, const Eigen::Vector3d& start) {
  clear();
  path_ = dragged_from_ = path;
  start_ = start;
  // An arc's axis handle is blue, like the axis drawn to it.
  const Eigen::Vector3d orange(1, 0.55, 0), blue(0.15, 0.45, 0.95);
  handles_->show(renderer,
                 PathHandlePoints(path, start),
                 std::holds_alternative<ArcPath>(path)
                     ? std::vector<Eigen::Vector3d>{orange, orange, blue}
                     : std::vector<Eigen::Vector3d>{});
  renderer->AddActor(preview_);
  UpdatePreview();
}

void PathHandles::OnDrag(int handle) {
  path_ = MovePathHandle(dragged_from_, start_, handle, handles_->position(handle));
  // The other handles follow the path (an arc's end goes round a moved centre).
  const auto points = PathHandlePoints(path_, start_);
  for (int i = 0; i < handles_->count(); ++i)
    if (i != handle) handles_->setPosition(i, points[static_cast<size_t>(i)]);
  UpdatePreview();
}

void PathHandles::UpdatePreview() {
  const auto samples = SamplePath(path_, start_);
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->InsertNextCell(static_cast<vtkIdType>(samples.size()));
  for (const Eigen::Vector3d& p : samples)
    lines->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
  if (std::holds_alternative<ArcPath>(path_)) {
    // The axis: from the centre to its handle.
    const auto handles = PathHandlePoints(path_, start_);
    lines->InsertNextCell(2);
    for (const Eigen::Vector3d& p : {handles[0], handles[2]})
      lines->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
  }
  line_->SetPoints(points);
  line_->SetLines(lines);
  line_->Modified();
}

}  // namespace drape
