#include "core/model/elevation_above.h"

#include <algorithm>
#include <limits>

namespace drape {
namespace {

double LeastDistance(const std::vector<Eigen::Vector2d>& points,
                     const ObstacleGeometry& obstacle,
                     double elevation) {
  double least = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : points)
    least = std::min(least, obstacle.Query({p.x(), p.y(), elevation}).distance);
  return least;
}

}  // namespace

// A distance is 1-Lipschitz, so lowering the sheet by (least distance −
// clearance) brings no point closer than the clearance: the march converges
// on the first touch from above and can never pass through a thin part.
std::optional<double> ElevationAbove(const std::vector<Eigen::Vector2d>& points,
                                     const ObstacleGeometry& obstacle,
                                     double clearance) {
  const std::optional<Eigen::AlignedBox3d> bounds = obstacle.Bounds();
  if (!bounds || points.empty()) return std::nullopt;
  const double bottom = bounds->min().z() - clearance;
  const double tolerance = 1e-9 * std::max(clearance, bounds->diagonal().norm());
  double elevation = bounds->max().z() + 2.0 * clearance;
  for (int i = 0; i < 10000 && elevation >= bottom; ++i) {
    const double gap = LeastDistance(points, obstacle, elevation) - clearance;
    if (gap <= tolerance) return elevation;
    elevation -= gap;
  }
  return std::nullopt;
}

}  // namespace drape
