// Plane polygon tests shared by the mesher and the pattern reader.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace drape {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// Signed area of the closed polygon (counter-clockwise positive).
double ShoelaceArea(const std::vector<Eigen::Vector2d>& polygon);

// Whether the closed segments pq and rs share a point. `zero` is the
// magnitude below which an orientation (a cross product) counts as collinear.
bool SegmentsTouch(const Eigen::Vector2d& p,
                   const Eigen::Vector2d& q,
                   const Eigen::Vector2d& r,
                   const Eigen::Vector2d& s,
                   double zero);

// Whether p lies inside the closed polygon (even-odd rule; a point on an
// edge may count either way).
bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

// The first two edges of the closed polygon that are not neighbours and
// share a point (edge i runs from vertex i to i + 1), or none: a simple
// polygon. `zero` as for SegmentsTouch. O(n²).
std::optional<std::pair<std::size_t, std::size_t>> FirstCrossing(
    const std::vector<Eigen::Vector2d>& polygon, double zero);

}  // namespace drape
