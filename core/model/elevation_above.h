// Where to start a drape over a form: the flat fabric lowered straight down
// onto an obstacle until it first comes within a clearance of it.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "core/model/obstacle_geometry.h"

namespace drape {

// The elevation at which the flat fabric (its points' reference x, y; every
// point at the same height), lowered from above the obstacle, first comes
// within `clearance` of it (the least distance of any point to the obstacle
// equals `clearance`). None when the obstacle has no top (Bounds() is none)
// or the fabric, lowered past the obstacle's bottom, never comes that close:
// it is not over it.
std::optional<double> ElevationAbove(const std::vector<Eigen::Vector2d>& points,
                                     const ObstacleGeometry& obstacle,
                                     double clearance);

}  // namespace drape
