// Nodes picked in the viewport: in pick mode a click picks the node of the
// shown state nearest the surface point (or unpicks it), the view marks
// the picked nodes on the step shown, and the editors that hold nodes hear
// of them with their reference positions.
#pragma once

#include <Eigen/Core>
#include <QObject>

#include <array>
#include <vector>

namespace drape {

class ViewController;
class VtkViewport;

class PickingController : public QObject {
  Q_OBJECT
 public:
  PickingController(VtkViewport* viewport, ViewController* view, QObject* parent = nullptr);

  // In the order picked.
  const std::vector<int>& picked() const { return picked_; }
  // Clicks pick instead of turning the camera.
  void setPickMode(bool on);

  // The node nearest `point` in the shown state is picked, or unpicked
  // when it was.
  void pickNear(const Eigen::Vector3d& point);
  void clear();
  // The markers drawn again where the picked nodes are in the shown state.
  void updateMarkers();

 signals:
  // The picked nodes and their reference (x, y).
  void pickedChanged(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);
  void message(const QString& text);

 private:
  void Publish();

  VtkViewport* viewport_;
  ViewController* view_;
  std::vector<int> picked_;
};

}  // namespace drape
