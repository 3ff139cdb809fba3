#include "core/model/imperfection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/model/mesh.h"

namespace drape {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Published outputs of SplitMix64 (Steele, Lea & Flood 2014; Vigna's
// splitmix64.c): the first three for seed 0, and the first five for seed
// 1234567 as listed by Rosetta Code ("Pseudo-random numbers/Splitmix64").
TEST(SplitMix64, MatchesPublishedOutputsForSeedZero) {
  SplitMix64 random(0);
  EXPECT_EQ(random.Next(), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(random.Next(), 0x6E789E6AA1B965F4ULL);
  EXPECT_EQ(random.Next(), 0x06C45D188009454FULL);
}

TEST(SplitMix64, MatchesPublishedOutputsForSeed1234567) {
  SplitMix64 random(1234567);
  EXPECT_EQ(random.Next(), 6457827717110365317ULL);
  EXPECT_EQ(random.Next(), 3203168211198807973ULL);
  EXPECT_EQ(random.Next(), 9817491932198370423ULL);
  EXPECT_EQ(random.Next(), 4593380528125082431ULL);
  EXPECT_EQ(random.Next(), 16408922859458223821ULL);
}

TEST(SplitMix64, UniformTakesTheTop53Bits) {
  // 0xE220A8397B1DCDAF >> 11 = 7956156453446585; times 2^-53.
  SplitMix64 random(0);
  EXPECT_EQ(random.NextUniform(), 7956156453446585.0 / 9007199254740992.0);
  for (int i = 0; i < 10000; ++i) {
    const double u = random.NextUniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

Eigen::Matrix<double, Eigen::Dynamic, 2> GridXY(int n, double size = 0.5) {
  return MeshRectangle(size, size, {0.1, -0.2}, n, n, 0).positions.leftCols<2>();
}

TEST(ImperfectionNodal, NodeIGetsTheIthDraw) {
  // First draw for seed 0: u = 0.8833108082136426 (see above), so node 0 gets
  // 0.003 · (2u − 1) = 0.0022998648492818558.
  const Eigen::VectorXd z =
      ImperfectionOffsets(GridXY(4), 0.003, 0, ImperfectionPattern::kNodal, 0);
  ASSERT_EQ(z.size(), 25);
  EXPECT_DOUBLE_EQ(z[0], 0.0022998648492818558);
  SplitMix64 random(0);
  for (int i = 0; i < z.size(); ++i) EXPECT_EQ(z[i], 0.003 * (2 * random.NextUniform() - 1)) << i;
}

TEST(ImperfectionNodal, ReproducibleBoundedAndSeedDependent) {
  const auto xy = GridXY(30);
  const double a = 1e-3;
  const Eigen::VectorXd z1 = ImperfectionOffsets(xy, a, 42, ImperfectionPattern::kNodal, 0);
  const Eigen::VectorXd z2 = ImperfectionOffsets(xy, a, 42, ImperfectionPattern::kNodal, 0);
  const Eigen::VectorXd z3 = ImperfectionOffsets(xy, a, 43, ImperfectionPattern::kNodal, 0);
  EXPECT_TRUE(z1 == z2);
  EXPECT_FALSE(z1 == z3);
  EXPECT_LE(z1.cwiseAbs().maxCoeff(), a);
  // 961 uniform draws: the extremes come close to ±a and the mean near 0
  // (standard error a / √(3 · 961) ≈ 0.019 a).
  EXPECT_GT(z1.maxCoeff(), 0.95 * a);
  EXPECT_LT(z1.minCoeff(), -0.95 * a);
  EXPECT_LT(std::abs(z1.mean()), 0.1 * a);
}

TEST(ImperfectionSmooth, ReproducibleBoundedAndSeedDependent) {
  const auto xy = GridXY(40);
  const double a = 2e-3;
  const Eigen::VectorXd z1 = ImperfectionOffsets(xy, a, 7, ImperfectionPattern::kSmooth, 0.1);
  const Eigen::VectorXd z2 = ImperfectionOffsets(xy, a, 7, ImperfectionPattern::kSmooth, 0.1);
  const Eigen::VectorXd z3 = ImperfectionOffsets(xy, a, 8, ImperfectionPattern::kSmooth, 0.1);
  EXPECT_TRUE(z1 == z2);
  EXPECT_FALSE(z1 == z3);
  EXPECT_LE(z1.cwiseAbs().maxCoeff(), a);
  EXPECT_LE(z3.cwiseAbs().maxCoeff(), a);
  // Not degenerate: a visible share of the amplitude on a 5 λ × 5 λ patch.
  EXPECT_GT(z1.cwiseAbs().maxCoeff(), 0.2 * a);
}

TEST(ImperfectionSmooth, SameSurfaceAtEveryMeshDensity) {
  const auto coarse = GridXY(10);
  const auto fine = GridXY(40);
  const Eigen::VectorXd zc =
      ImperfectionOffsets(coarse, 1e-3, 99, ImperfectionPattern::kSmooth, 0.2);
  const Eigen::VectorXd zf = ImperfectionOffsets(fine, 1e-3, 99, ImperfectionPattern::kSmooth, 0.2);
  // Coarse node (i, j) is fine node (4i, 4j).
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i) {
      const int c = j * 11 + i, f = (4 * j) * 41 + 4 * i;
      ASSERT_EQ(coarse(c, 0), fine(f, 0));
      ASSERT_EQ(coarse(c, 1), fine(f, 1));
      EXPECT_EQ(zc[c], zf[f]) << "node (" << i << ", " << j << ")";
    }
}

TEST(ImperfectionSmooth, SlopeBoundedByTheShortestWavelength) {
  // Each wave has wavelength ≥ λ/2, so |∇z| ≤ a · 2π / (λ/2) and neighbouring
  // nodes differ by at most that times their distance.
  const double a = 1e-3, lambda = 0.1;
  const Mesh mesh = MeshRectangle(0.5, 0.5, {0, 0}, 50, 50, 0);
  const Eigen::VectorXd z =
      ImperfectionOffsets(mesh.positions.leftCols<2>(), a, 5, ImperfectionPattern::kSmooth, lambda);
  const double slope = a * 4 * kPi / lambda;
  double steepest = 0;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      const int p = mesh.quads(e, k), q = mesh.quads(e, (k + 1) % 4);
      const double d = (mesh.positions.row(p) - mesh.positions.row(q)).norm();
      EXPECT_LE(std::abs(z[p] - z[q]), slope * d);
      steepest = std::max(steepest, std::abs(z[p] - z[q]) / d);
    }
  // ... and it is a wavy surface, not a tilt: the slope reaches a fair share.
  EXPECT_GT(steepest, 0.05 * slope);
}

TEST(Imperfection, ZeroAmplitudeIsFlat) {
  const auto xy = GridXY(5);
  EXPECT_TRUE(ImperfectionOffsets(xy, 0, 1, ImperfectionPattern::kSmooth, 0.1).isZero(0));
  EXPECT_TRUE(ImperfectionOffsets(xy, 0, 1, ImperfectionPattern::kNodal, 0).isZero(0));
}

TEST(Imperfection, RejectsBadParameters) {
  const auto xy = GridXY(3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ImperfectionOffsets(xy, -1e-3, 1, ImperfectionPattern::kSmooth, 0.1),
               std::invalid_argument);
  EXPECT_THROW(ImperfectionOffsets(xy, -1e-3, 1, ImperfectionPattern::kNodal, 0.1),
               std::invalid_argument);
  EXPECT_THROW(ImperfectionOffsets(xy, nan, 1, ImperfectionPattern::kNodal, 0.1),
               std::invalid_argument);
  EXPECT_THROW(ImperfectionOffsets(xy, 1e-3, 1, ImperfectionPattern::kSmooth, 0),
               std::invalid_argument);
  EXPECT_THROW(ImperfectionOffsets(xy, 1e-3, 1, ImperfectionPattern::kSmooth, -0.1),
               std::invalid_argument);
  EXPECT_THROW(ImperfectionOffsets(xy, 1e-3, 1, ImperfectionPattern::kSmooth, nan),
               std::invalid_argument);
  // The wavelength means nothing to the nodal pattern.
  EXPECT_NO_THROW(ImperfectionOffsets(xy, 1e-3, 1, ImperfectionPattern::kNodal, 0));
  try {
    ImperfectionOffsets(xy, 1e-3, 1, ImperfectionPattern::kSmooth, -0.5);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wavelength = -0.5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace drape
