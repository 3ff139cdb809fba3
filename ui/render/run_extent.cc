// What every frame of a run shares, found once over all its states: the box
// the camera is fitted to, so that it does not jump between frames, and one
// range for the colour bar.
#include "ui/render/frame_renderer.h"

#include <algorithm>
#include <cmath>

#include "ui/render/scene_actors.h"

namespace drape {

Eigen::AlignedBox3d RunBounds(const Scene& scene, const std::vector<const ShellState*>& states) {
  Eigen::AlignedBox3d box;
  for (const ShellState* s : states)
    for (int i = 0; i < s->positions.rows(); ++i)
      box.extend(s->positions.row(i).transpose().eval());
  // Finite obstacles the part rests on belong in the picture.
  for (const auto& o : scene.obstacles) {
    if (const auto* b = std::get_if<BoxShape>(&o.shape)) {
      box.extend(Eigen::Vector3d(b->min[0], b->min[1], b->min[2]));
      box.extend(Eigen::Vector3d(b->max[0], b->max[1], b->max[2]));
    } else if (const auto* s = std::get_if<SphereShape>(&o.shape)) {
      const Eigen::Vector3d c(s->center[0], s->center[1], s->center[2]);
      box.extend((c.array() - s->radius).matrix());
      box.extend((c.array() + s->radius).matrix());
    }
  }
  if (box.isEmpty()) box.extend(Eigen::Vector3d::Zero());
  return box;
}

std::vector<Eigen::Vector3d> GripperPathPoints(const Scene& scene, const ShellModel& model) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& line : GripperPaths(scene, model))
    points.insert(points.end(), line.begin(), line.end());
  return points;
}

std::array<double, 2> FieldRange(FieldKind kind,
                                 const ShellModel& model,
                                 const std::vector<const ShellState*>& states,
                                 const std::vector<double>& contact_pressure) {
  std::array<double, 2> range{INFINITY, -INFINITY};
  auto take = [&](const Eigen::VectorXd& v) {
    if (!v.size()) return;
    range[0] = std::min(range[0], v.minCoeff());
    range[1] = std::max(range[1], v.maxCoeff());
  };
  if (kind == FieldKind::kFrictionState) return {0.0, 2.0};  // none, sticking, sliding
  if (kind == FieldKind::kContactPressure) {
    take(Eigen::Map<const Eigen::VectorXd>(contact_pressure.data(),
                                           static_cast<Eigen::Index>(contact_pressure.size())));
  } else {
    for (const ShellState* s : states) take(EvaluateField(kind, model, *s));
  }
  if (!(range[0] <= range[1])) range = {0.0, 1.0};
  return range;
}

}  // namespace drape
