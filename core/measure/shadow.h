// The shadow a part casts along gravity, as a drapemeter sees it: the union
// of its surface projected on a plane across gravity, computed exactly as a
// polygon union (Clipper), not on a raster, so that folds that lie over one
// another count once.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/model/mesh.h"

namespace drape {

// A plane across `down` through `origin`, with in-plane axes u, v such that
// u × v = −down: seen from above (against gravity), u points right and v up.
// u is the global x axis made orthogonal to `down` (y when x is parallel to it).
struct ShadowPlane {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();

  static ShadowPlane Across(const Eigen::Vector3d& down, const Eigen::Vector3d& origin);
  Eigen::Vector2d Project(const Eigen::Vector3d& p) const;
};

// Closed rings in plane coordinates [m], without a repeated last point.
// Outer boundaries run counter-clockwise, holes clockwise, so that the
// signed areas add up to the shadow's area.
struct Shadow {
  std::vector<std::vector<Eigen::Vector2d>> rings;
  double area = 0;  // [m²]
};

// The shadow of the surface with nodes at `positions` (one row per node of
// `quads`), each quad split into two triangles along its 0–2 diagonal.
// Coordinates are rounded to 1 nm for the union, far below any part's
// resolution. Throws std::invalid_argument for a non-finite position.
Shadow CastShadow(const Eigen::MatrixX3d& positions,
                  const Eigen::Matrix<int, Eigen::Dynamic, 4>& quads,
                  const ShadowPlane& plane);

// The signed area of a ring (shoelace): positive counter-clockwise.
double RingArea(const std::vector<Eigen::Vector2d>& ring);

}  // namespace drape
