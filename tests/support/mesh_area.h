// The area of a shell model's flat mesh, summed over its quads split into two
// triangles each: exact for planar quads, and independent of the Gauss
// weights the engine integrates with.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/fe/shell_model.h"

namespace drape::test {

inline double MeshArea(const ShellModel& model) {
  double area = 0;
  const auto& x = model.reference.positions;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const auto q = model.mesh.quads.row(e);
    const Eigen::Vector3d a = x.row(q(0)), b = x.row(q(1)), c = x.row(q(2)), d = x.row(q(3));
    area += 0.5 * ((b - a).cross(c - a).norm() + (c - a).cross(d - a).norm());
  }
  return area;
}

}  // namespace drape::test
