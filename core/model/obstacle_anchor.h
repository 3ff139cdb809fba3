// Where a user takes hold of an obstacle to move it, and the obstacle moved.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "core/model/scene.h"

namespace drape {

// A plane's point, a box's centre, a cylinder's point on its axis, a
// sphere's centre. None for a triangle mesh: a scene places a mesh where
// its file puts it, so there is nothing to move.
std::optional<Eigen::Vector3d> ObstacleAnchor(const Obstacle& obstacle);

// `obstacle` translated by `by` (a mesh is returned as it is).
Obstacle Translated(const Obstacle& obstacle, const Eigen::Vector3d& by);

}  // namespace drape
