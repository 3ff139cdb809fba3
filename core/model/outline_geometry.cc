#include "core/model/outline_geometry.h"

#include "core/model/overloaded.h"

#include <algorithm>
#include <cmath>

namespace drape {
namespace {

// Even-odd rule: a ray to +x crosses the boundary an odd number of times.
bool InsidePolygon(const std::vector<Vec2>& v, const Vec2& p) {
  bool inside = false;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i][1] > p[1]) != (v[j][1] > p[1])) {
      double x = v[j][0] + (p[1] - v[j][1]) * (v[i][0] - v[j][0]) / (v[i][1] - v[j][1]);
      if (p[0] < x) inside = !inside;
    }
  }
  return inside;
}

double PolygonArea(const std::vector<Vec2>& v) {
  double twice = 0;
  for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    twice += v[j][0] * v[i][1] - v[i][0] * v[j][1];
  return std::abs(twice) / 2;
}

Bounds2 VertexBounds(const std::vector<Vec2>& vertices) {
  Bounds2 b{vertices.front(), vertices.front()};
  for (const auto& v : vertices)
    for (int k = 0; k < 2; ++k) {
      b.min[k] = std::min(b.min[k], v[k]);
      b.max[k] = std::max(b.max[k], v[k]);
    }
  return b;
}

}  // namespace

double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  double dx = b[0] - a[0], dy = b[1] - a[1];
  double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

double DistanceToLoop(const std::vector<Vec2>& loop, const Vec2& p) {
  double best = INFINITY;
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
    best = std::min(best, DistanceToSegment(p, loop[j], loop[i]));
  return best;
}

double PieceArea(const PatternPiece& piece) {
  double area = PolygonArea(piece.boundary);
  for (const auto& hole : piece.holes) area -= PolygonArea(hole);
  return area;
}

Bounds2 OutlineBounds(const Outline& outline) {
  return std::visit(Overloaded{
                        [](const RectangleOutline& r) {
                          return Bounds2{
                              {r.center[0] - r.size[0] / 2, r.center[1] - r.size[1] / 2},
                              {r.center[0] + r.size[0] / 2, r.center[1] + r.size[1] / 2}};
                        },
                        [](const DiskOutline& d) {
                          return Bounds2{{d.center[0] - d.radius, d.center[1] - d.radius},
                                         {d.center[0] + d.radius, d.center[1] + d.radius}};
                        },
                        [](const PolygonOutline& p) { return VertexBounds(p.vertices); },
                        [](const PatternOutline& p) { return VertexBounds(p.shape.boundary); },
                    },
                    outline);
}

double OutlineSize(const Outline& outline) {
  Bounds2 b = OutlineBounds(outline);
  return std::hypot(b.max[0] - b.min[0], b.max[1] - b.min[1]);
}

double PartsSize(const Scene& scene) {
  Bounds2 all = OutlineBounds(scene.fabric.outline);
  for (const Fabric& part : scene.other_parts) {
    const Bounds2 b = OutlineBounds(part.outline);
    for (int k = 0; k < 2; ++k) {
      all.min[k] = std::min(all.min[k], b.min[k]);
      all.max[k] = std::max(all.max[k], b.max[k]);
    }
  }
  return std::hypot(all.max[0] - all.min[0], all.max[1] - all.min[1]);
}

double OutlineArea(const Outline& outline) {
  return std::visit(Overloaded{
                        [](const RectangleOutline& r) { return r.size[0] * r.size[1]; },
                        [](const DiskOutline& d) { return M_PI * d.radius * d.radius; },
                        [](const PolygonOutline& p) { return PolygonArea(p.vertices); },
                        [](const PatternOutline& p) { return PieceArea(p.shape); },
                    },
                    outline);
}

double DistanceToOutline(const Outline& outline, const Vec2& p) {
  return std::visit(Overloaded{
                        [&](const RectangleOutline& r) {
                          double dx = std::max(0.0, std::abs(p[0] - r.center[0]) - r.size[0] / 2);
                          double dy = std::max(0.0, std::abs(p[1] - r.center[1]) - r.size[1] / 2);
                          return std::hypot(dx, dy);
                        },
                        [&](const DiskOutline& d) {
                          double r = std::hypot(p[0] - d.center[0], p[1] - d.center[1]);
                          return std::max(0.0, r - d.radius);
                        },
                        [&](const PolygonOutline& poly) {
                          if (InsidePolygon(poly.vertices, p)) return 0.0;
                          return DistanceToLoop(poly.vertices, p);
                        },
                        [&](const PatternOutline& pattern) {
                          const PatternPiece& piece = pattern.shape;
                          if (!InsidePolygon(piece.boundary, p))
                            return DistanceToLoop(piece.boundary, p);
                          for (const auto& hole : piece.holes)
                            if (InsidePolygon(hole, p)) return DistanceToLoop(hole, p);
                          return 0.0;
                        },
                    },
                    outline);
}

std::vector<Vec2> OutlineCorners(const Outline& outline) {
  return std::visit(Overloaded{
                        [](const RectangleOutline& r) {
                          Bounds2 b = OutlineBounds(r);
                          return std::vector<Vec2>{{b.min[0], b.min[1]},
                                                   {b.max[0], b.min[1]},
                                                   {b.max[0], b.max[1]},
                                                   {b.min[0], b.max[1]}};
                        },
                        [](const DiskOutline&) { return std::vector<Vec2>{}; },
                        [](const PolygonOutline& p) { return p.vertices; },
                        [](const PatternOutline& p) { return p.shape.boundary; },
                    },
                    outline);
}

}  // namespace drape
