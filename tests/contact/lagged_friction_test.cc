// The lagged friction potential (core/contact/lagged_friction.h) against
// its definition: f₁ = f₀', force = −∂D/∂x and stiffness = ∂²D/∂x² by
// central differences, on both sides of the stick/slide slip ε.

#include "core/contact/lagged_friction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <vector>

namespace drape {
namespace {

constexpr double kEpsilon = 2e-5;  // [m]
constexpr double kLimit = 3e-4;    // μ λ_n [N]

Eigen::Matrix<double, 3, 2> TiltedBasis() {
  return TangentBasis(Eigen::Vector3d(0.3, -0.4, 0.866).normalized());
}

TEST(LaggedFriction, MobilisedShareIsTheSlopeOfThePotentialAndReachesOneAtEpsilon) {
  for (double y : {0.0, 0.1 * kEpsilon, 0.5 * kEpsilon, 0.99 * kEpsilon, 1.5 * kEpsilon}) {
    const double d = 1e-4 * kEpsilon;
    const double slope = (FrictionSlipPotential(y + d, kEpsilon) -
                          FrictionSlipPotential(std::max(0.0, y - d), kEpsilon)) /
                         (y + d - std::max(0.0, y - d));
    EXPECT_NEAR(slope, FrictionMobilised(y, kEpsilon), 1e-4) << "y/eps = " << y / kEpsilon;
  }
  EXPECT_DOUBLE_EQ(FrictionMobilised(kEpsilon, kEpsilon), 1.0);
  EXPECT_DOUBLE_EQ(FrictionMobilised(0.5 * kEpsilon, kEpsilon), 0.75);  // 2·½ − ¼
  // f₀ is continuous at ε: ε/ε·ε − ε/3 + ε/3 = ε.
  EXPECT_NEAR(FrictionSlipPotential(kEpsilon * (1 - 1e-12), kEpsilon), kEpsilon, 1e-15);
}

TEST(LaggedFriction, TangentBasisIsOrthonormalAndNormalToN) {
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.4, 0.866).normalized();
  const auto t = TangentBasis(n);
  EXPECT_NEAR((t.transpose() * t - Eigen::Matrix2d::Identity()).norm(), 0, 1e-15);
  EXPECT_NEAR((t.transpose() * n).norm(), 0, 1e-15);
}

TEST(LaggedFriction, ForceAndStiffnessAreTheDerivativesOfThePotential) {
  const auto basis = TiltedBasis();
  const Eigen::Vector3d anchor(0.01, 0.02, -0.03);
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.4, 0.866).normalized();
  const Eigen::Vector3d direction = (basis * Eigen::Vector2d(0.8, -0.6)) + 0.2 * n;
  for (double y : {0.0, 0.3, 0.97, 1.03, 4.0}) {
    const Eigen::Vector3d x = anchor + y * kEpsilon * direction;
    const FrictionResponse at = EvaluateFriction(x, anchor, basis, kLimit, kEpsilon);
    const double h = 1e-4 * kEpsilon;
    Eigen::Vector3d gradient;
    Eigen::Matrix3d hessian;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
      const auto plus = EvaluateFriction(x + e, anchor, basis, kLimit, kEpsilon);
      const auto minus = EvaluateFriction(x - e, anchor, basis, kLimit, kEpsilon);
      gradient(k) = (plus.energy - minus.energy) / (2 * h);
      hessian.col(k) = -(plus.force - minus.force) / (2 * h);
    }
    SCOPED_TRACE("slip / eps = " + std::to_string(at.slip / kEpsilon));
    EXPECT_LT((gradient + at.force).norm(), 1e-6 * kLimit);
    // At y = 0 the Hessian is the limit 2/ε; differences straddling it
    // miss the −|u|³/(3ε²) term's first order, h/(2ε) = 5e-5 of it.
    EXPECT_LT((hessian - at.stiffness).norm(), (y == 0 ? 1e-4 : 1e-5) * at.stiffness.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(at.stiffness);
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * at.stiffness.norm());
    // Slip normal to the plane costs nothing.
    EXPECT_LT((at.stiffness * n).norm(), 1e-12 * at.stiffness.norm());
  }
}

TEST(LaggedFriction, ForceIsCoulombsLimitOnceSliding) {
  const auto basis = TiltedBasis();
  const Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  const Eigen::Vector3d slip = basis * Eigen::Vector2d(3 * kEpsilon, 4 * kEpsilon);
  const auto r = EvaluateFriction(anchor + slip, anchor, basis, kLimit, kEpsilon);
  EXPECT_NEAR(r.force.norm(), kLimit, 1e-15);
  EXPECT_NEAR(r.force.normalized().dot(-slip.normalized()), 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(r.mobilised, 1.0);
  // Half of ε: three quarters of it.
  const auto half = EvaluateFriction(
      anchor + basis * Eigen::Vector2d(0.5 * kEpsilon, 0), anchor, basis, kLimit, kEpsilon);
  EXPECT_NEAR(half.force.norm(), 0.75 * kLimit, 1e-15);
}

}  // namespace
}  // namespace drape
