// Point–triangle and edge–edge distances (core/geometry/primitive_distance.h)
// against closed forms, and against dense sampling of the primitives for
// random configurations: the returned distance is attained by the returned
// closest points and no sample comes closer.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "core/geometry/primitive_distance.h"
#include "support/pair_differences.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;

TEST(PrimitiveDistance, PointAgainstEachRegionOfATriangle) {
  const V3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  struct Case {
    V3 p;
    double distance;
    V3 barycentric;
  };
  const Case cases[] = {
      {{0.5, 0.5, 0.3}, 0.3, {0.5, 0.25, 0.25}},   // face, above
      {{0.5, 0.5, -0.7}, 0.7, {0.5, 0.25, 0.25}},  // face, below
      {{-1, -1, 0}, std::sqrt(2.0), {1, 0, 0}},    // vertex a
      {{3, -1, 1}, std::sqrt(3.0), {0, 1, 0}},     // vertex b
      {{-0.5, 3, 0}, std::sqrt(1.25), {0, 0, 1}},  // vertex c
      {{1, -2, 0}, 2, {0.5, 0.5, 0}},              // edge ab
      {{-3, 1.5, 4}, 5, {0.25, 0, 0.75}},          // edge ca
      {{2, 2, 0}, std::sqrt(2.0), {0, 0.5, 0.5}},  // edge bc
  };
  for (const Case& k : cases) {
    const PointTriangleDistance d = PointTriangle(k.p, a, b, c);
    EXPECT_NEAR(std::sqrt(d.squared), k.distance, 1e-14) << k.p.transpose();
    EXPECT_LT((d.barycentric - k.barycentric).norm(), 1e-14) << k.p.transpose();
  }
}

TEST(PrimitiveDistance, EdgesCrossingParallelAndApart) {
  // Skew, crossing in projection: the gap between them.
  EdgeEdgeDistance d = EdgeEdge(V3(-1, 0, 0), V3(1, 0, 0), V3(0.5, -1, 0.4), V3(0.5, 1, 0.4));
  EXPECT_NEAR(std::sqrt(d.squared), 0.4, 1e-15);
  EXPECT_NEAR(d.s, 0.75, 1e-15);
  EXPECT_NEAR(d.t, 0.5, 1e-15);
  // Touching: zero.
  d = EdgeEdge(V3(-1, 0, 0), V3(1, 0, 0), V3(0, -1, 0), V3(0, 1, 0));
  EXPECT_EQ(d.squared, 0);
  // Parallel and overlapping: the offset; parallel and apart: end to end.
  d = EdgeEdge(V3(0, 0, 0), V3(2, 0, 0), V3(1, 0.3, 0), V3(3, 0.3, 0));
  EXPECT_NEAR(std::sqrt(d.squared), 0.3, 1e-15);
  d = EdgeEdge(V3(0, 0, 0), V3(1, 0, 0), V3(4, 0, 0.5), V3(2, 0, 0.5));
  EXPECT_NEAR(std::sqrt(d.squared), std::hypot(1.0, 0.5), 1e-15);
  // Lines that meet beyond the segments: an end point is closest.
  d = EdgeEdge(V3(0, 0, 0), V3(1, 0, 0), V3(3, -1, 0), V3(3, 1, 0));
  EXPECT_NEAR(std::sqrt(d.squared), 2, 1e-15);
  EXPECT_EQ(d.s, 1);
  // A degenerate segment is a point.
  d = EdgeEdge(V3(0.5, 2, 0), V3(0.5, 2, 0), V3(0, 0, 0), V3(1, 0, 0));
  EXPECT_NEAR(std::sqrt(d.squared), 2, 1e-15);
  EXPECT_NEAR(d.t, 0.5, 1e-15);
}

V3 RandomPoint(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return V3(n(rng), n(rng), n(rng));
}

TEST(PrimitiveDistance, PointTriangleIsTheMinimumOverTheTriangle) {
  std::mt19937_64 rng(17);
  const int samples = 160;
  for (int trial = 0; trial < 300; ++trial) {
    const V3 a = RandomPoint(rng), b = RandomPoint(rng), c = RandomPoint(rng), p = RandomPoint(rng);
    const PointTriangleDistance d = PointTriangle(p, a, b, c);
    const V3& w = d.barycentric;
    EXPECT_GE(w.minCoeff(), -1e-12);
    EXPECT_NEAR(w.sum(), 1, 1e-12);
    EXPECT_NEAR((p - (w(0) * a + w(1) * b + w(2) * c)).squaredNorm(), d.squared, 1e-12);
    double sampled = INFINITY;
    for (int i = 0; i <= samples; ++i)
      for (int j = 0; i + j <= samples; ++j) {
        const double u = double(i) / samples, v = double(j) / samples;
        sampled = std::min(sampled, (p - ((1 - u - v) * a + u * b + v * c)).squaredNorm());
      }
    EXPECT_LE(d.squared, sampled + 1e-12) << "trial " << trial;
    // The sampling's own error: half a sample spacing of the longest edge.
    const double spacing = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / samples;
    EXPECT_GE(std::sqrt(d.squared), std::sqrt(sampled) - spacing) << "trial " << trial;
  }
}

TEST(PrimitiveDistance, EdgeEdgeIsTheMinimumOverBothSegments) {
  std::mt19937_64 rng(23);
  const int samples = 400;
  for (int trial = 0; trial < 300; ++trial) {
    const V3 a0 = RandomPoint(rng), a1 = RandomPoint(rng), b0 = RandomPoint(rng);
    // Every fifth pair nearly parallel.
    const V3 b1 =
        trial % 5 == 0 ? V3(b0 + (a1 - a0) * 0.7 + 1e-9 * RandomPoint(rng)) : RandomPoint(rng);
    const EdgeEdgeDistance d = EdgeEdge(a0, a1, b0, b1);
    EXPECT_GE(d.s, 0);
    EXPECT_LE(d.s, 1);
    EXPECT_GE(d.t, 0);
    EXPECT_LE(d.t, 1);
    double sampled = INFINITY;
    for (int i = 0; i <= samples; ++i)
      for (int j = 0; j <= samples; ++j)
        sampled = std::min(
            sampled,
            ((a0 + (a1 - a0) * (double(i) / samples)) - (b0 + (b1 - b0) * (double(j) / samples)))
                .squaredNorm());
    // Segments parallel to within 1e-7 rad are taken as parallel: the
    // distance is then exact to 1e-7 of their length.
    const double parallel_slack = trial % 5 == 0 ? 1e-7 * (a1 - a0).norm() : 1e-12;
    EXPECT_LE(std::sqrt(d.squared), std::sqrt(sampled) + parallel_slack) << "trial " << trial;
    const double spacing = ((a1 - a0).norm() + (b1 - b0).norm()) / samples;
    EXPECT_GE(std::sqrt(d.squared), std::sqrt(sampled) - spacing) << "trial " << trial;
  }
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

using Coordinates = Eigen::Matrix<double, 12, 1>;
using Derivatives = DistanceDerivatives (*)(const V3&, const V3&, const V3&, const V3&);

DistanceDerivatives At(Derivatives f, const Coordinates& x) {
  return f(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), x.segment<3>(9));
}

// Central differences of the value (against the gradient) and of the
// gradient (against the Hessian), relative to their largest entries.
void ExpectDerivativesMatchDifferences(Derivatives f, const Coordinates& x, const char* regime) {
  const DistanceDerivatives d = At(f, x);
  const auto [gradient, hessian] = test::CentralDifferences(
      [&](const Coordinates& y) {
        const DistanceDerivatives e = At(f, y);
        return std::pair{e.squared, e.gradient};
      },
      x,
      1e-6);
  EXPECT_LT((gradient - d.gradient).norm(), 1e-7 * std::max(1.0, d.gradient.norm())) << regime;
  EXPECT_LT((hessian - d.hessian).norm(), 1e-6 * std::max(1.0, d.hessian.norm())) << regime;
  EXPECT_LT((d.hessian - d.hessian.transpose()).norm(), 1e-12 * std::max(1.0, d.hessian.norm()))
      << regime;
}

Coordinates Stack(const V3& a, const V3& b, const V3& c, const V3& e) {
  Coordinates x;
  x << a, b, c, e;
  return x;
}

TEST(PrimitiveDistance, PointTriangleDerivativesInEveryRegion) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  for (int trial = 0; trial < 20; ++trial) {
    const V3 a = RandomPoint(rng), b = RandomPoint(rng), c = RandomPoint(rng);
    const V3 n = (b - a).cross(c - a).normalized();
    const double height = u(rng) * (trial % 2 ? 1 : -1);
    // Face: above an interior point. Edge ab: beyond its middle, away from
    // c. Vertex a: beyond a, away from the triangle.
    const double s = u(rng) * 0.5, t = u(rng) * 0.4;
    const V3 face = a + s * (b - a) + t * (c - a) + height * n;
    const V3 outward_ab =
        ((b - a).cross(n)).normalized() * ((b - a).cross(n).dot(c - a) > 0 ? -1.0 : 1.0);
    const V3 edge = a + u(rng) * (b - a) + 0.5 * outward_ab + height * n;
    const V3 vertex = a - 0.6 * ((b - a).normalized() + (c - a).normalized()) + height * n;
    const PointTriangleDistance r = PointTriangle(edge, a, b, c);
    ASSERT_GT(r.barycentric(0), 1e-3);
    ASSERT_GT(r.barycentric(1), 1e-3);
    ASSERT_EQ(r.barycentric(2), 0);
    ASSERT_EQ(PointTriangle(vertex, a, b, c).barycentric, V3(1, 0, 0));
    ExpectDerivativesMatchDifferences(PointTriangleDerivatives, Stack(face, a, b, c), "face");
    ExpectDerivativesMatchDifferences(PointTriangleDerivatives, Stack(edge, a, b, c), "edge");
    ExpectDerivativesMatchDifferences(PointTriangleDerivatives, Stack(vertex, a, b, c), "vertex");
  }
}

TEST(PrimitiveDistance, EdgeEdgeDerivativesInEveryRegion) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  for (int trial = 0; trial < 20; ++trial) {
    const V3 a0 = RandomPoint(rng), a1 = RandomPoint(rng);
    const V3 m = a0 + u(rng) * (a1 - a0);
    V3 side = (a1 - a0).cross(RandomPoint(rng)).normalized();
    const V3 gap = (a1 - a0).cross(side).normalized() * u(rng);
    // Interior of both: a segment through m + gap along `side`.
    const V3 b0 = m + gap - 0.7 * side, b1 = m + gap + 0.9 * side;
    // The end of one: segment c passes beside a1, beyond the end of a (its
    // closest point 0.4 along it).
    const V3 c0 = a1 + 0.3 * (a1 - a0).normalized() + gap - 0.4 * side, c1 = c0 + side;
    // Both ends: b points away from a beyond a1.
    const V3 d0 = a1 + 0.3 * (a1 - a0).normalized() + gap,
             d1 = d0 + 0.8 * (a1 - a0).normalized() + 0.2 * side;
    const EdgeEdgeDistance inner = EdgeEdge(a0, a1, b0, b1);
    ASSERT_GT(inner.s, 1e-3);
    ASSERT_LT(inner.s, 1 - 1e-3);
    ASSERT_GT(inner.t, 1e-3);
    ASSERT_LT(inner.t, 1 - 1e-3);
    ASSERT_EQ(EdgeEdge(a0, a1, c0, c1).s, 1);
    ASSERT_NEAR(EdgeEdge(a0, a1, c0, c1).t, 0.4, 1e-9);
    ASSERT_EQ(EdgeEdge(a0, a1, d0, d1).s, 1);
    ASSERT_EQ(EdgeEdge(a0, a1, d0, d1).t, 0);
    ExpectDerivativesMatchDifferences(EdgeEdgeDerivatives, Stack(a0, a1, b0, b1), "interior");
    ExpectDerivativesMatchDifferences(EdgeEdgeDerivatives, Stack(a0, a1, c0, c1), "one end");
    ExpectDerivativesMatchDifferences(EdgeEdgeDerivatives, Stack(a0, a1, d0, d1), "both ends");
  }
}

}  // namespace
}  // namespace drape
