#include "core/measure/shadow.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <polyclipping/clipper.hpp>

namespace drape {
namespace {

constexpr double kGrid = 1e-9;  // [m]: Clipper works on integers

ClipperLib::IntPoint OnGrid(const Eigen::Vector2d& p) {
  return {static_cast<ClipperLib::cInt>(std::llround(p.x() / kGrid)),
          static_cast<ClipperLib::cInt>(std::llround(p.y() / kGrid))};
}

std::vector<Eigen::Vector2d> FromGrid(const ClipperLib::Path& path) {
  std::vector<Eigen::Vector2d> ring;
  ring.reserve(path.size());
  for (const auto& q : path) ring.emplace_back(q.X * kGrid, q.Y * kGrid);
  return ring;
}

ClipperLib::Paths UnionOf(const ClipperLib::Paths& paths) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  ClipperLib::Paths united;
  clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return united;
}

// The union of many small polygons, by halves: Clipper's sweep slows down
// with the edges that neighbouring triangles share, and each group's union
// has lost them (86 400 triangles: 8.3 s at once, see docs/performance.md).
ClipperLib::Paths Union(ClipperLib::Paths paths) {
  constexpr size_t kGroup = 64;
  std::vector<ClipperLib::Paths> groups;
  for (size_t i = 0; i < paths.size(); i += kGroup)
    groups.push_back(UnionOf(
        ClipperLib::Paths(paths.begin() + i, paths.begin() + std::min(paths.size(), i + kGroup))));
  while (groups.size() > 1) {
    std::vector<ClipperLib::Paths> merged;
    for (size_t i = 0; i < groups.size(); i += 2) {
      if (i + 1 == groups.size()) {
        merged.push_back(std::move(groups[i]));
        continue;
      }
      ClipperLib::Paths both = std::move(groups[i]);
      both.insert(both.end(), groups[i + 1].begin(), groups[i + 1].end());
      merged.push_back(UnionOf(both));
    }
    groups = std::move(merged);
  }
  return groups.empty() ? ClipperLib::Paths{} : std::move(groups.front());
}

}  // namespace

ShadowPlane ShadowPlane::Across(const Eigen::Vector3d& down, const Eigen::Vector3d& origin) {
  const Eigen::Vector3d g = down.normalized();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX() - g.x() * g;
  if (u.norm() < 1e-6) u = Eigen::Vector3d::UnitY() - g.y() * g;
  ShadowPlane plane;
  plane.origin = origin;
  plane.u = u.normalized();
  plane.v = (-g).cross(plane.u);
  return plane;
}

Eigen::Vector2d ShadowPlane::Project(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - origin;
  return {d.dot(u), d.dot(v)};
}

double RingArea(const std::vector<Eigen::Vector2d>& ring) {
  double twice = 0;
  for (size_t i = 0, n = ring.size(); i < n; ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

Shadow CastShadow(const Eigen::MatrixX3d& positions,
                  const Eigen::Matrix<int, Eigen::Dynamic, 4>& quads,
                  const ShadowPlane& plane) {
  if (!positions.allFinite())
    throw std::invalid_argument("the state has a position that is not a finite number");
  std::vector<ClipperLib::IntPoint> flat(positions.rows());
  for (int i = 0; i < positions.rows(); ++i)
    flat[i] = OnGrid(plane.Project(positions.row(i).transpose()));
  ClipperLib::Paths triangles;
  triangles.reserve(2 * quads.rows());
  for (int e = 0; e < quads.rows(); ++e)
    for (const auto& corners : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      ClipperLib::Path t{
          flat[quads(e, corners[0])], flat[quads(e, corners[1])], flat[quads(e, corners[2])]};
      // The non-zero rule counts a clockwise triangle as −1: every one is
      // turned counter-clockwise, so overlapping layers add instead of cancelling.
      if (!ClipperLib::Orientation(t)) ClipperLib::ReversePath(t);
      triangles.push_back(std::move(t));
    }
  ClipperLib::Paths united = Union(std::move(triangles));
  Shadow shadow;
  for (const auto& path : united) {
    shadow.rings.push_back(FromGrid(path));
    shadow.area += RingArea(shadow.rings.back());
  }
  return shadow;
}

}  // namespace drape
