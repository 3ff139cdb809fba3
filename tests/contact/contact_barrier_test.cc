// C-IPC's barrier (core/contact/contact_barrier.h): its derivatives against
// finite differences, C² where it switches on, infinite at the offset, and a
// pair's potential gradient and Hessian against finite differences of its
// energy for point–triangle and edge–edge pairs inside the active band.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

#include "core/contact/contact_barrier.h"
#include "support/pair_differences.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;
using Coordinates = Eigen::Matrix<double, 12, 1>;

TEST(ContactBarrier, DerivativesAgainstDifferences) {
  const double s_hat = 2.5e-7;
  for (double s : {1e-10, 1e-9, 3e-8, 1e-7, 2e-7, 2.4e-7}) {
    const double h = 1e-6 * s;
    const BarrierValue b = ClampedLogBarrier(s, s_hat), p = ClampedLogBarrier(s + h, s_hat),
                       m = ClampedLogBarrier(s - h, s_hat);
    EXPECT_NEAR(b.first, (p.value - m.value) / (2 * h), 1e-7 * std::abs(b.first) + 1e-20) << s;
    EXPECT_NEAR(b.second, (p.first - m.first) / (2 * h), 1e-6 * std::abs(b.second) + 1e-12) << s;
    EXPECT_GT(b.value, 0);
    EXPECT_LT(b.first, 0);  // repulsive: the energy falls as the gap grows
  }
}

TEST(ContactBarrier, SwitchesOnC2AndBlocksTheOffset) {
  const double s_hat = 1.0;
  const BarrierValue at = ClampedLogBarrier(s_hat, s_hat), beyond = ClampedLogBarrier(2, s_hat);
  EXPECT_EQ(at.value, 0);
  EXPECT_EQ(beyond.second, 0);
  // Approaching ŝ from inside, b, b' and b'' all go to 0.
  const BarrierValue near = ClampedLogBarrier(s_hat * (1 - 1e-6), s_hat);
  EXPECT_LT(near.value, 1e-17);
  EXPECT_LT(std::abs(near.first), 1e-11);
  EXPECT_LT(std::abs(near.second), 1e-5);
  EXPECT_EQ(ClampedLogBarrier(0, s_hat).value, INFINITY);
  EXPECT_EQ(ClampedLogBarrier(-1, s_hat).value, INFINITY);
}

using Derivatives = DistanceDerivatives (*)(const V3&, const V3&, const V3&, const V3&);

PairPotential At(Derivatives f, const Coordinates& x, double offset, double activation) {
  return BarrierPotential(f(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6), x.segment<3>(9)),
                          offset,
                          activation,
                          1e3);
}

void ExpectPotentialMatchesDifferences(Derivatives f,
                                       const Coordinates& x,
                                       double offset,
                                       double activation) {
  const PairPotential p = At(f, x, offset, activation);
  ASSERT_GT(p.energy, 0);
  const auto [gradient, hessian] = test::CentralDifferences(
      [&](const Coordinates& y) {
        const PairPotential e = At(f, y, offset, activation);
        return std::pair{e.energy, e.gradient};
      },
      x,
      1e-9);
  EXPECT_LT((gradient - p.gradient).norm(), 1e-5 * p.gradient.norm());
  EXPECT_LT((hessian - p.hessian).norm(), 1e-4 * p.hessian.norm());
}

Coordinates Stack(const V3& a, const V3& b, const V3& c, const V3& e) {
  Coordinates x;
  x << a, b, c, e;
  return x;
}

TEST(ContactBarrier, PairPotentialDerivativesInsideTheBand) {
  // Fabric-sized: a 5 mm triangle, thickness ξ = 0.5 mm, d̂ = 0.25 mm; the
  // point at 0.6 mm (inside the band ξ … ξ + d̂) above the face, beside an
  // edge, beside a vertex; two edges 0.6 mm apart.
  const double offset = 5e-4, activation = 2.5e-4, gap = 6e-4;
  const V3 a(0, 0, 0), b(5e-3, 0, 0), c(1e-3, 4e-3, 0);
  ExpectPotentialMatchesDifferences(
      PointTriangleDerivatives, Stack(V3(2e-3, 1e-3, gap), a, b, c), offset, activation);
  ExpectPotentialMatchesDifferences(PointTriangleDerivatives,
                                    Stack(V3(2e-3, -gap * 0.6, gap * 0.8), a, b, c),
                                    offset,
                                    activation);
  ExpectPotentialMatchesDifferences(PointTriangleDerivatives,
                                    Stack(V3(-gap * 0.6, -gap * 0.3, gap * 0.74), a, b, c),
                                    offset,
                                    activation);
  ExpectPotentialMatchesDifferences(
      EdgeEdgeDerivatives,
      Stack(V3(0, 0, 0), V3(5e-3, 0, 0), V3(2e-3, -2e-3, gap), V3(3e-3, 3e-3, gap)),
      offset,
      activation);
  // Beyond the band: nothing.
  const Coordinates far = Stack(V3(2e-3, 1e-3, 8e-4), a, b, c);
  EXPECT_EQ(At(PointTriangleDerivatives, far, offset, activation).energy, 0);
  EXPECT_EQ(At(PointTriangleDerivatives, far, offset, activation).gradient.norm(), 0);
}

// Nearly parallel edges (sin²θ ≈ 2.5e-5, far below the mollifier's 1e-3):
// the mollified potential's gradient and Hessian against differences, and it
// vanishes as the edges turn parallel.
TEST(ContactBarrier, MollifiedEdgeEdgePotentialNearParallel) {
  const double offset = 5e-4, activation = 2.5e-4, gap = 6e-4;
  const V3 a0(0, 0, 0), a1(5e-3, 0, 0);
  const double threshold = MollifierThreshold(a0, a1, a0, a1);
  auto potential = [&](const Coordinates& x) {
    const V3 p0 = x.segment<3>(0), p1 = x.segment<3>(3), q0 = x.segment<3>(6), q1 = x.segment<3>(9);
    return MollifiedEdgeEdgePotential(
        EdgeEdgeDerivatives(p0, p1, q0, q1), p0, p1, q0, q1, threshold, offset, activation, 1e3);
  };
  const Coordinates x = Stack(a0, a1, V3(1e-3, 1e-5, gap), V3(4e-3, -1e-5, gap));
  const PairPotential p = potential(x);
  ASSERT_GT(p.energy, 0);
  const auto [gradient, hessian] = test::CentralDifferences(
      [&](const Coordinates& y) {
        const PairPotential e = potential(y);
        return std::pair{e.energy, e.gradient};
      },
      x,
      1e-10);
  EXPECT_LT((gradient - p.gradient).norm(), 1e-5 * p.gradient.norm());
  EXPECT_LT((hessian - p.hessian).norm(), 1e-4 * p.hessian.norm());
  // Unmollified, the same pair has more energy; exactly parallel, none.
  const PairPotential bare =
      BarrierPotential(EdgeEdgeDerivatives(a0, a1, V3(1e-3, 1e-5, gap), V3(4e-3, -1e-5, gap)),
                       offset,
                       activation,
                       1e3);
  EXPECT_LT(p.energy, bare.energy);
  EXPECT_EQ(potential(Stack(a0, a1, V3(1e-3, 0, gap), V3(4e-3, 0, gap))).energy, 0);
}

}  // namespace
}  // namespace drape
