#include "core/model/obstacle_anchor.h"

#include "core/model/overloaded.h"
#include "core/model/vec3_eigen.h"

namespace drape {
namespace {

void Add(Vec3& v, const Eigen::Vector3d& by) {
  for (int i = 0; i < 3; ++i) v[i] += by[i];
}

}  // namespace

std::optional<Eigen::Vector3d> ObstacleAnchor(const Obstacle& obstacle) {
  return std::visit(
      Overloaded{
          [](const PlaneShape& p) -> std::optional<Eigen::Vector3d> { return ToEigen(p.point); },
          [](const BoxShape& b) -> std::optional<Eigen::Vector3d> {
            return 0.5 * (ToEigen(b.min) + ToEigen(b.max));
          },
          [](const CylinderShape& c) -> std::optional<Eigen::Vector3d> { return ToEigen(c.point); },
          [](const SphereShape& s) -> std::optional<Eigen::Vector3d> { return ToEigen(s.center); },
          [](const MeshShape& m) -> std::optional<Eigen::Vector3d> { return ToEigen(m.at); },
      },
      obstacle.shape);
}

Obstacle Translated(const Obstacle& obstacle, const Eigen::Vector3d& by) {
  Obstacle moved = obstacle;
  std::visit(Overloaded{
                 [&](PlaneShape& p) { Add(p.point, by); },
                 [&](BoxShape& b) {
                   Add(b.min, by);
                   Add(b.max, by);
                 },
                 [&](CylinderShape& c) { Add(c.point, by); },
                 [&](SphereShape& s) { Add(s.center, by); },
                 [&](MeshShape& m) { Add(m.at, by); },
             },
             moved.shape);
  return moved;
}

}  // namespace drape
