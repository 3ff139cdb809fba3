#include "core/fe/prescribed_motion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drape {
namespace {

// dx/dλ by central differences, to check the analytic rates.
Eigen::Vector3d NumericVelocity(const Path& path, double lambda, const Eigen::Vector3d& x0) {
  const double h = 1e-6;
  return (MotionAt(path, lambda + h).Apply(x0) - MotionAt(path, lambda - h).Apply(x0)) / (2 * h);
}

TEST(PrescribedMotion, LineMovesByItsVectorTimesLambda) {
  const Path line = LinePath{{0.1, -0.2, 0.3}};
  const Eigen::Vector3d x0(1, 2, 3);
  EXPECT_LT((MotionAt(line, 0.25).Apply(x0) - (x0 + 0.25 * Eigen::Vector3d(0.1, -0.2, 0.3))).norm(),
            1e-15);
  EXPECT_LT((MotionAt(line, 0.5).Velocity(x0) - Eigen::Vector3d(0.1, -0.2, 0.3)).norm(), 1e-15);
}

TEST(PrescribedMotion, ArcIsARigidRotationAboutItsAxis) {
  // The paper's fold: the end (−0.1, 0, 0) about the y axis through the
  // origin by 180° lands on (0.1, 0, 0) and passes over the top at λ = ½.
  const Path arc = ArcPath{{0, 0, 0}, {0, 1, 0}, 180.0};
  const Eigen::Vector3d end(-0.1, 0, 0);
  EXPECT_LT((MotionAt(arc, 1.0).Apply(end) - Eigen::Vector3d(0.1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((MotionAt(arc, 0.5).Apply(end) - Eigen::Vector3d(0, 0, 0.1)).norm(), 1e-15);
  for (double l : {0.1, 0.5, 0.9}) {
    // Distance to the axis is kept; the speed is the radius times the angle.
    EXPECT_NEAR(MotionAt(arc, l).Apply(end).norm(), 0.1, 1e-15);
    EXPECT_LT((MotionAt(arc, l).Velocity(end) - NumericVelocity(arc, l, end)).norm(), 1e-8);
    EXPECT_NEAR(MotionAt(arc, l).Velocity(end).norm(), 0.1 * M_PI, 1e-12);
  }
  EXPECT_NEAR(PathLength(arc, end), 0.1 * M_PI, 1e-5);
}

TEST(PrescribedMotion, KeyframesPassThroughTheirPointsAtEqualSteps) {
  KeyframesPath k;
  k.points = {{0.1, 0, 0}, {0.1, 0, 0.1}, {0, 0, 0.2}};
  const Eigen::Vector3d x0 = Eigen::Vector3d::Zero();
  for (Interpolation interpolation : {Interpolation::kLinear, Interpolation::kSmooth}) {
    k.interpolation = interpolation;
    const Path path = k;
    EXPECT_LT(MotionAt(path, 0).Apply(x0).norm(), 1e-15);
    for (int i = 1; i <= 3; ++i) {
      const Eigen::Vector3d expected(k.points[i - 1][0], k.points[i - 1][1], k.points[i - 1][2]);
      EXPECT_LT((MotionAt(path, i / 3.0).Apply(x0) - expected).norm(), 1e-14);
    }
    for (double l : {0.1, 0.4, 0.8})
      EXPECT_LT((MotionAt(path, l).Velocity(x0) - NumericVelocity(path, l, x0)).norm(), 1e-7);
  }
  // Linear: straight between keys. Smooth: the velocity is continuous at a key.
  k.interpolation = Interpolation::kLinear;
  EXPECT_LT((MotionAt(k, 0.5).Apply(x0) - Eigen::Vector3d(0.1, 0, 0.05)).norm(), 1e-15);
  k.interpolation = Interpolation::kSmooth;
  const Eigen::Vector3d before = MotionAt(k, 1.0 / 3 - 1e-9).Velocity(x0);
  const Eigen::Vector3d after = MotionAt(k, 1.0 / 3 + 1e-9).Velocity(x0);
  EXPECT_LT((before - after).norm(), 1e-6);
}

}  // namespace
}  // namespace drape
