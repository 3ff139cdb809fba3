#include "core/model/polygon_checks.h"

#include <algorithm>

namespace drape {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double ShoelaceArea(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    twice += Cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice;
}

bool SegmentsTouch(const Eigen::Vector2d& p,
                   const Eigen::Vector2d& q,
                   const Eigen::Vector2d& r,
                   const Eigen::Vector2d& s,
                   double zero) {
  auto orientation =
      [zero](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
        const double o = Cross(b - a, c - a);
        return o > zero ? 1 : (o < -zero ? -1 : 0);
      };
  auto within = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    // c lies in the bounding box of ab (used when a, b, c are collinear).
    return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
  };
  const int o1 = orientation(p, q, r);
  const int o2 = orientation(p, q, s);
  const int o3 = orientation(r, s, p);
  const int o4 = orientation(r, s, q);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && within(p, q, r)) return true;
  if (o2 == 0 && within(p, q, s)) return true;
  if (o3 == 0 && within(r, s, p)) return true;
  if (o4 == 0 && within(r, s, q)) return true;
  return false;
}

bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < b.x() + (p.y() - b.y()) * (a.x() - b.x()) / (a.y() - b.y()))
      inside = !inside;
  }
  return inside;
}

std::optional<std::pair<std::size_t, std::size_t>> FirstCrossing(
    const std::vector<Eigen::Vector2d>& polygon, double zero) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through vertex 0
      if (SegmentsTouch(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n], zero))
        return std::pair{i, j};
    }
  }
  return std::nullopt;
}

}  // namespace drape
