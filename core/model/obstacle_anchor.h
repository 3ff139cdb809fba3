// Where a user takes hold of an obstacle to move it, and the obstacle moved.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "core/model/scene.h"

namespace drape {

// A plane's point, a box's centre, a cylinder's point on its axis, a
// sphere's centre, where a triangle mesh's file origin is placed (`at`).
// None is kept for a shape that has no such point.
std::optional<Eigen::Vector3d> ObstacleAnchor(const Obstacle& obstacle);

// `obstacle` translated by `by`.
Obstacle Translated(const Obstacle& obstacle, const Eigen::Vector3d& by);

}  // namespace drape
