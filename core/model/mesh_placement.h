// Where a mesh obstacle's file sits in the world: MeshShape's scale,
// rotation_deg and at as one affine map, the same for contact and drawing.
#pragma once

#include <Eigen/Geometry>

#include "core/model/scene.h"

namespace drape {

// x_world = at + R_z(rotation_deg) · diag(scale) · x_file.
Eigen::Affine3d MeshPlacement(const MeshShape& shape);

}  // namespace drape
