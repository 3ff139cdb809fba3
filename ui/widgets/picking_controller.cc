#include "ui/widgets/picking_controller.h"

#include <algorithm>

#include "ui/widgets/view_controller.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {

PickingController::PickingController(VtkViewport* viewport, ViewController* view, QObject* parent)
    : QObject(parent), viewport_(viewport), view_(view) {
  connect(viewport_, &VtkViewport::picked, this, &PickingController::pickNear);
  connect(view_, &ViewController::stepShown, this, &PickingController::updateMarkers);
  connect(view_, &ViewController::rendererChanged, this, &PickingController::updateMarkers);
}

void PickingController::setPickMode(bool on) {
  viewport_->setPickMode(on);
  emit message(on ? "pick mode: click the fabric to pick or unpick a node"
                  : QString("%1 nodes picked").arg(picked_.size()));
}

void PickingController::pickNear(const Eigen::Vector3d& point) {
  if (!view_->model()) return;
  const Eigen::MatrixX3d& x = view_->shownPositions();
  Eigen::Index nearest = 0;
  (x.rowwise() - point.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  const int node = static_cast<int>(nearest);
  const auto it = std::find(picked_.begin(), picked_.end(), node);
  const bool added = it == picked_.end();
  if (added)
    picked_.push_back(node);
  else
    picked_.erase(it);
  Publish();
  emit message(QString("node %1 %2; %3 nodes picked")
                   .arg(node)
                   .arg(added ? "picked" : "unpicked")
                   .arg(picked_.size()));
}

void PickingController::clear() {
  picked_.clear();
  Publish();
}

void PickingController::Publish() {
  std::vector<std::array<double, 2>> at;
  if (const auto& model = view_->model())
    for (int n : picked_)
      at.push_back({model->reference.positions(n, 0), model->reference.positions(n, 1)});
  emit pickedChanged(picked_, at);
  updateMarkers();
}

void PickingController::updateMarkers() {
  if (!view_->renderer()) return;
  const Eigen::MatrixX3d& x = view_->shownPositions();
  std::vector<Eigen::Vector3d> points;
  for (int node : picked_)
    if (node < x.rows()) points.push_back(x.row(node).transpose());
  viewport_->showMarkers(view_->renderer()->renderer(), points);
}

}  // namespace drape
