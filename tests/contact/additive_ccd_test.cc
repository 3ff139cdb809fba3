// The collision-free step filter (core/contact/additive_ccd.h): a point
// falling onto a triangle stops short of the offset by the closed-form
// time; pairs that separate keep the whole step; and for random pairs and
// motions no point of the allowed part of the step comes within the
// offset (checked by dense sampling of the straight path).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/contact/additive_ccd.h"
#include "core/geometry/primitive_distance.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;

TEST(AdditiveCcd, AFallingPointStopsShortOfTheOffset) {
  const V3 a(-1, -1, 0), b(2, -1, 0), c(-1, 2, 0), zero = V3::Zero();
  AccdSettings s;
  s.offset = 0.5;
  // 1 above the face, falling 2: the offset is reached at t = 0.25; the
  // filter stops once the gap is down to 10 % (t = 0.225) or a little before.
  const double t = PointTriangleStepBound(V3(0, 0, 1), a, b, c, V3(0, 0, -2), zero, zero, zero, s);
  EXPECT_GT(t, 0.2);
  EXPECT_LE(t, 0.225 + 1e-12);
  // Rising, or sliding along at a constant height: the whole step.
  EXPECT_EQ(PointTriangleStepBound(V3(0, 0, 1), a, b, c, V3(0, 0, 2), zero, zero, zero, s), 1);
  EXPECT_EQ(PointTriangleStepBound(V3(0, 0, 1), a, b, c, V3(0.3, 0.2, 0), zero, zero, zero, s), 1);
  // Moving all together: no relative motion.
  const V3 d(0.4, -3, 7);
  EXPECT_EQ(PointTriangleStepBound(V3(0, 0, 1), a, b, c, d, d, d, d, s), 1);
  // Already inside the offset: no step at all.
  EXPECT_EQ(PointTriangleStepBound(V3(0, 0, 0.4), a, b, c, V3(0, 0, 1), zero, zero, zero, s), 0);
}

TEST(AdditiveCcd, CrossingEdgesStopBeforeTheyMeet) {
  AccdSettings s;
  s.offset = 0.1;
  const V3 zero = V3::Zero();
  // Edge b 1 above edge a and across it, moving down 3: they would meet at
  // t = 1/3, reach the offset at 0.3.
  const double t = EdgeEdgeStepBound(V3(-1, 0, 0),
                                     V3(1, 0, 0),
                                     V3(0, -1, 1),
                                     V3(0, 1, 1),
                                     zero,
                                     zero,
                                     V3(0, 0, -3),
                                     V3(0, 0, -3),
                                     s);
  EXPECT_GT(t, 0.2);
  EXPECT_LT(t, 0.3);
}

TEST(AdditiveCcd, APairStopsAtTheBoundItCannotLower) {
  const V3 a(-1, -1, 0), b(2, -1, 0), c(-1, 2, 0), zero = V3::Zero();
  AccdSettings s;
  s.offset = 0.5;
  // The falling point of the first test, limited to 0.1 < 0.225 by an
  // earlier pair: it stops there. Limited to 0.5, it stops short as alone.
  s.max_t = 0.1;
  EXPECT_EQ(PointTriangleStepBound(V3(0, 0, 1), a, b, c, V3(0, 0, -2), zero, zero, zero, s), 0.1);
  s.max_t = 0.5;
  const double t = PointTriangleStepBound(V3(0, 0, 1), a, b, c, V3(0, 0, -2), zero, zero, zero, s);
  EXPECT_GT(t, 0.2);
  EXPECT_LE(t, 0.225 + 1e-12);
}

TEST(AdditiveCcd, OutOfStepsItKeepsWhatItAdvanced) {
  // A point sliding 1 along a face 1e-4 above the offset: each step
  // advances by 0.9 · 1e-4 of the slide, so 50 steps reach t ≈ 4.5e-3 —
  // safe, since the height never changes — where giving up used to
  // return 0 and stall the Newton step.
  const V3 a(-1, -1, 0), b(2, -1, 0), c(-1, 2, 0), zero = V3::Zero();
  AccdSettings s;
  s.offset = 0.5;
  s.max_steps = 50;
  const V3 p(0, 0, 0.5 + 1e-4), slide(1, 0, 0);
  const double t = PointTriangleStepBound(p, a, b, c, slide, zero, zero, zero, s);
  // Steps: (1 − keep) · gap / closing first, then 0.9 · gap / closing.
  EXPECT_NEAR(t, (0.9 + 49 * 0.9) * 1e-4, 1e-9);
  s.max_steps = 12000;  // enough for 1 / 0.9e-4 ≈ 11112 steps: the whole slide
  EXPECT_EQ(PointTriangleStepBound(p, a, b, c, slide, zero, zero, zero, s), 1);
}

V3 Random(std::mt19937_64& rng, double scale) {
  std::normal_distribution<double> n(0.0, scale);
  return V3(n(rng), n(rng), n(rng));
}

TEST(AdditiveCcd, NoAllowedStepComesWithinTheOffset) {
  std::mt19937_64 rng(41);
  AccdSettings s;
  s.offset = 0.05;
  int stopped = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::array<V3, 4> x, dx;
    for (int i = 0; i < 4; ++i) {
      x[i] = Random(rng, 1.0);
      dx[i] = Random(rng, 1.5);
    }
    const bool edges = trial % 2 == 1;
    auto distance = [&](double t) {
      std::array<V3, 4> y;
      for (int i = 0; i < 4; ++i) y[i] = x[i] + t * dx[i];
      return std::sqrt(edges ? EdgeEdge(y[0], y[1], y[2], y[3]).squared
                             : PointTriangle(y[0], y[1], y[2], y[3]).squared);
    };
    if (distance(0) <= s.offset) continue;
    const double t =
        edges ? EdgeEdgeStepBound(x[0], x[1], x[2], x[3], dx[0], dx[1], dx[2], dx[3], s)
              : PointTriangleStepBound(x[0], x[1], x[2], x[3], dx[0], dx[1], dx[2], dx[3], s);
    ASSERT_GE(t, 0);
    ASSERT_LE(t, 1);
    stopped += t < 1;
    double closest = INFINITY;
    for (int k = 0; k <= 2000; ++k) closest = std::min(closest, distance(t * k / 2000));
    EXPECT_GT(closest, s.offset) << "trial " << trial << ", t = " << t;
  }
  EXPECT_GT(stopped, 20);  // the test sees pairs that would have crossed
}

}  // namespace
}  // namespace drape
