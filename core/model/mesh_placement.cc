#include "core/model/mesh_placement.h"

#include <numbers>

#include "core/model/vec3_eigen.h"

namespace drape {

Eigen::Affine3d MeshPlacement(const MeshShape& shape) {
  const double turn = shape.rotation_deg * std::numbers::pi / 180.0;
  Eigen::Affine3d placement = Eigen::Affine3d::Identity();
  placement.translate(ToEigen(shape.at));
  placement.rotate(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()));
  placement.scale(ToEigen(shape.scale));
  return placement;
}

}  // namespace drape
