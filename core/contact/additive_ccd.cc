#include "core/contact/additive_ccd.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/primitive_distance.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;

// `squared_distance(x)` of the four moving points; `split` of them (1 for a
// point against a triangle, 2 for two edges) belong to the first primitive.
template <typename SquaredDistance>
double Advance(std::array<V3, 4> x,
               std::array<V3, 4> dx,
               int split,
               SquaredDistance squared_distance,
               const AccdSettings& s) {
  // Relative motion only: subtract the mean displacement.
  V3 mean = V3::Zero();
  for (const V3& d : dx) mean += d / 4;
  for (V3& d : dx) d -= mean;
  double first = 0, second = 0;
  for (int i = 0; i < 4; ++i)
    (i < split ? first : second) = std::max(i < split ? first : second, dx[i].norm());
  const double closing = first + second;  // the gap closes at most this fast
  const double t_max = std::min(1.0, s.max_t);
  if (closing == 0) return t_max;
  const double xi = s.offset;
  auto gap_of = [&](double d2) {
    const double d = std::sqrt(d2);
    return (d2 - xi * xi) / (d + xi);  // d − ξ, without cancellation
  };
  double gap = gap_of(squared_distance(x));
  if (!(gap > 0)) return 0.0;  // already at or through the offset
  const double target = s.keep * gap;
  double t = 0;
  double step = (1 - s.keep) * gap / closing;
  // Each step is at most 0.9 of the gap over the closing speed, so the gap
  // at every t reached stays above a tenth of the last one: t is safe.
  for (int k = 0; k < s.max_steps; ++k) {
    for (int i = 0; i < 4; ++i) x[i] += step * dx[i];
    gap = gap_of(squared_distance(x));
    if (t > 0 && gap < target) return t;
    t += step;
    if (t >= t_max) return t_max;
    step = 0.9 * gap / closing;
  }
  return t;
}

}  // namespace

double PointTriangleStepBound(const V3& p,
                              const V3& a,
                              const V3& b,
                              const V3& c,
                              const V3& dp,
                              const V3& da,
                              const V3& db,
                              const V3& dc,
                              const AccdSettings& settings) {
  return Advance(
      {p, a, b, c},
      {dp, da, db, dc},
      1,
      [](const std::array<V3, 4>& x) { return PointTriangle(x[0], x[1], x[2], x[3]).squared; },
      settings);
}

double EdgeEdgeStepBound(const V3& a0,
                         const V3& a1,
                         const V3& b0,
                         const V3& b1,
                         const V3& da0,
                         const V3& da1,
                         const V3& db0,
                         const V3& db1,
                         const AccdSettings& settings) {
  return Advance(
      {a0, a1, b0, b1},
      {da0, da1, db0, db1},
      2,
      [](const std::array<V3, 4>& x) { return EdgeEdge(x[0], x[1], x[2], x[3]).squared; },
      settings);
}

}  // namespace drape
