// The broad phase of self-contact (core/contact/self_proximity.h): its pairs
// equal those of testing every pair, and the smallest distance between the
// layers of a sheet folded flat onto itself is the gap between them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/contact/self_proximity.h"

namespace drape {
namespace {

// nx × ny quads over [0, lx] × [0, ly], flat at z = 0.
Mesh Grid(int nx, int ny, double lx, double ly) {
  Mesh m;
  m.positions.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.positions.row(j * (nx + 1) + i) << lx * i / nx, ly * j / ny, 0.0;
  m.quads.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n = j * (nx + 1) + i;
      m.quads.row(j * nx + i) << n, n + 1, n + nx + 2, n + nx + 1;
    }
  return m;
}

// The sheet [0, 2] × [0, 1] folded flat at x = 1: the part beyond lies on
// the part before, `gap` above it, mirrored.
Positions FoldedFlat(const Mesh& m, double gap) {
  Positions x = m.positions;
  for (int i = 0; i < x.rows(); ++i)
    if (m.positions(i, 0) > 1 + 1e-12) x.row(i) << 2 - m.positions(i, 0), m.positions(i, 1), gap;
  return x;
}

TEST(SelfProximity, AFlatSheetHasNoPairs) {
  const Mesh m = Grid(10, 5, 2, 1);
  const SelfProximity proximity(m, 0.25);
  const ProximityPairs pairs = proximity.Candidates(m.positions, 0.1);
  EXPECT_TRUE(pairs.point_triangle.empty());
  EXPECT_TRUE(pairs.edge_edge.empty());
  EXPECT_EQ(proximity.SmallestDistance(m.positions, 0.1), INFINITY);
}

TEST(SelfProximity, LayersFoldedFlatAreTheGapApart) {
  const Mesh m = Grid(20, 5, 2, 1);
  // Parts within 0.25 of each other in the rest shape (the fold's hinge) do
  // not count; every other pair of the two layers is at least the gap apart.
  const SelfProximity proximity(m, 0.25);
  for (double gap : {1e-4, 3e-3, 0.05}) {
    const Positions x = FoldedFlat(m, gap);
    EXPECT_NEAR(proximity.SmallestDistance(x, 0.1), gap, 1e-15 + 1e-12 * gap) << gap;
  }
  // Beyond the reach: no pair.
  EXPECT_EQ(proximity.SmallestDistance(FoldedFlat(m, 0.2), 0.1), INFINITY);
}

TEST(SelfProximity, HashFindsTheSamePairsAsTestingEveryPair) {
  const Mesh m = Grid(12, 8, 2, 1);
  const SelfProximity proximity(m, 0.2);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 6; ++trial) {
    // Folded with a gap, then crumpled: smooth waves and noise bring parts of
    // both layers within reach at many different distances.
    Positions x = FoldedFlat(m, 0.02 + 0.01 * trial);
    const double a = 0.03 * u(rng), k = 3 + trial;
    for (int i = 0; i < x.rows(); ++i) {
      x(i, 2) += a * std::sin(k * x(i, 0)) * std::cos(k * x(i, 1)) + 0.01 * u(rng);
      x(i, 0) += 0.01 * u(rng);
    }
    for (double reach : {0.01, 0.04, 0.15}) {
      const ProximityPairs hashed = proximity.Candidates(x, reach);
      const ProximityPairs brute = proximity.CandidatesByBruteForce(x, reach);
      EXPECT_EQ(hashed.point_triangle, brute.point_triangle) << trial << " " << reach;
      EXPECT_EQ(hashed.edge_edge, brute.edge_edge) << trial << " " << reach;
      if (reach == 0.15) {
        EXPECT_GT(brute.point_triangle.size(), 100u) << trial;
      }
    }
  }
}

TEST(SelfProximity, SweptGridFindsTheSamePairsAsTestingEveryPair) {
  const Mesh m = Grid(12, 8, 2, 1);
  const SelfProximity proximity(m, 0.2);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 4; ++trial) {
    const Positions x = FoldedFlat(m, 0.05);
    // The upper layer pressed down and sheared, with noise: some primitives
    // sweep far, some barely move.
    Positions motion = Positions::Zero(x.rows(), 3);
    for (int i = 0; i < x.rows(); ++i) {
      if (m.positions(i, 0) > 1) motion.row(i) << 0.1 * trial * u(rng), 0.0, -0.03 * trial;
      motion.row(i) += 0.005 * Eigen::RowVector3d(u(rng), u(rng), u(rng));
    }
    for (double gap : {0.002, 0.02}) {
      const ProximityPairs gridded = proximity.SweptCandidates(x, motion, gap);
      const ProximityPairs brute = proximity.SweptCandidatesByBruteForce(x, motion, gap);
      EXPECT_EQ(gridded.point_triangle, brute.point_triangle) << trial << " " << gap;
      EXPECT_EQ(gridded.edge_edge, brute.edge_edge) << trial << " " << gap;
      // Conservative: every pair that does come within the gap somewhere
      // along the motion is a candidate.
      for (int k = 0; k <= 20; ++k) {
        const ProximityPairs at = proximity.CandidatesByBruteForce(x + k / 20.0 * motion, gap);
        for (const auto& pair : at.point_triangle)
          EXPECT_TRUE(std::binary_search(
              gridded.point_triangle.begin(), gridded.point_triangle.end(), pair))
              << trial << " " << gap << " " << k;
        for (const auto& pair : at.edge_edge)
          EXPECT_TRUE(std::binary_search(gridded.edge_edge.begin(), gridded.edge_edge.end(), pair))
              << trial << " " << gap << " " << k;
      }
      if (trial > 1) {
        EXPECT_GT(brute.point_triangle.size(), 100u) << trial;
      }
    }
  }
}

}  // namespace
}  // namespace drape
