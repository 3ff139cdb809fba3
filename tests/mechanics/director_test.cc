// Finite rotations of the directors: the rotation built from a director is a
// rotation taking E₃ to it everywhere on the sphere, turned-over ends included.
#include "core/mechanics/director.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <numbers>

namespace drape {
namespace {

void ExpectRotationTo(const Eigen::Vector3d& t) {
  const Eigen::Matrix3d r = RotationFromDirector(t);
  ASSERT_TRUE(r.allFinite()) << "t = " << t.transpose();
  EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14)
      << "t = " << t.transpose();
  EXPECT_NEAR(r.determinant(), 1.0, 1e-14) << "t = " << t.transpose();
  EXPECT_LT((r.col(2) - t).cwiseAbs().maxCoeff(), 1e-15) << "t = " << t.transpose();
}

TEST(Director, RotationFromDirectorHoldsAtAndNearTheTurnedOverPole) {
  ExpectRotationTo(-Eigen::Vector3d::UnitZ());  // a 180° fold: 0/0 in the paper's formula
  for (double tilt : {1e-12, 1e-8, 1e-4, 1e-2})
    ExpectRotationTo(
        Eigen::Vector3d(std::sin(tilt), 0.3 * std::sin(tilt), -std::cos(tilt)).normalized());
}

TEST(Director, RotationFromDirectorCoversTheWholeSphere) {
  // A spiral of directors from the top pole to the bottom one.
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    const double z = 1.0 - 2.0 * i / n;
    const double phi = 2.399963229728653 * i;  // the golden angle
    const double rho = std::sqrt(std::max(0.0, 1 - z * z));
    ExpectRotationTo(Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), z));
  }
}

TEST(Director, ExpRotationAtWholeTurnsIsTheIdentity) {
  // Rodrigues' formula at θ = 2π k: sin θ/θ and (1 − cos θ)/θ² vanish up to
  // the rounding of θ.
  for (int k = 1; k <= 4; ++k) {
    const Eigen::Vector3d w = Eigen::Vector3d(0, 1, 0) * (2 * std::numbers::pi * k);
    EXPECT_LT((ExpRotation(w) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
  }
  const Eigen::Matrix3d half = ExpRotation(Eigen::Vector3d(0, std::numbers::pi, 0));
  EXPECT_LT((half.col(2) + Eigen::Vector3d::UnitZ()).norm(), 1e-15);
}

}  // namespace
}  // namespace drape
