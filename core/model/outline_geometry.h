// Plane geometry of a part's outline in reference (flat) coordinates.
#pragma once

#include <vector>

#include "core/model/scene.h"

namespace drape {

struct Bounds2 {
  Vec2 min{0, 0};
  Vec2 max{0, 0};
};

Bounds2 OutlineBounds(const Outline& outline);

// Diagonal of the bounding box [m]: the part's characteristic size.
double OutlineSize(const Outline& outline);

// Diagonal of the box around every part of the scene's fabric [m].
double PartsSize(const Scene& scene);

// Area enclosed by the outline, its holes left out [m²].
double OutlineArea(const Outline& outline);

// Distance from p to the part (0 inside or on the boundary; inside a hole,
// the distance to the hole's edge) [m].
double DistanceToOutline(const Outline& outline, const Vec2& p);

// A pattern piece's area: its cut line's, its cut-outs left out [m²].
double PieceArea(const PatternPiece& piece);

// Distance from p to the segment ab [m].
double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// Distance from p to the nearest point on the closed loop's edges [m].
double DistanceToLoop(const std::vector<Vec2>& loop, const Vec2& p);

// The outline's corners: a rectangle's four (counter-clockwise from the
// lower left) or a polygon's or a pattern piece's cut-line vertices; a disk
// has none.
std::vector<Vec2> OutlineCorners(const Outline& outline);

}  // namespace drape
