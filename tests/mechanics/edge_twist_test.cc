// The twist of a loaded edge segment about its own axis: the rotation of the
// directors about the axis when the edge stays on it, zero for any rigid
// swing of the segment, and derivatives that match central differences taken
// along the DOFs' own increments (director.h).
#include "core/mechanics/edge_twist.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "core/mechanics/director.h"

namespace drape {
namespace {

using Dofs = Eigen::Matrix<double, 10, 1>;

// A segment along y from (0, 0, 0) to (0, 1, 0), flat (directors E₃).
const EdgeTwistReference kReference{Eigen::Vector3d::UnitY(),
                                    {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}};
const Eigen::Vector3d kX0 = Eigen::Vector3d::Zero(), kX1 = Eigen::Vector3d::UnitY();

Eigen::Matrix3d Turned(const Eigen::Vector3d& rotation) {
  return ExpRotation(rotation) * RotationFromDirector(Eigen::Vector3d::UnitZ());
}

TEST(EdgeTwist, IsTheDirectorsRotationAboutAnAxisTheEdgeKeeps) {
  for (double angle : {-3.0, -1.0, 0.0, 0.4, 2.5, 3.1}) {
    const Eigen::Matrix3d r = Turned(angle * Eigen::Vector3d::UnitY());
    EXPECT_NEAR(EvaluateEdgeTwist(kReference, kX0, kX1, r, r).angle, angle, 1e-14);
  }
  // Each node counts half.
  const Eigen::Matrix3d r0 = Turned(0.2 * Eigen::Vector3d::UnitY());
  const Eigen::Matrix3d r1 = Turned(0.6 * Eigen::Vector3d::UnitY());
  EXPECT_NEAR(EvaluateEdgeTwist(kReference, kX0, kX1, r0, r1).angle, 0.4, 1e-14);
}

TEST(EdgeTwist, IsZeroForARigidSwingOfTheSegment) {
  // A rotation about an axis normal to the edge takes the edge where the
  // swing does: it turns nothing about the edge's axis.
  for (const Eigen::Vector3d& axis :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.6, 0, -0.8)})
    for (double angle : {0.3, 1.5, 2.8}) {
      const Eigen::Matrix3d q = ExpRotation(angle * axis);
      const Eigen::Matrix3d r = Turned(angle * axis);
      const Eigen::Vector3d offset(0.3, -2.0, 0.7);
      const double twist =
          EvaluateEdgeTwist(kReference, offset + q * kX0, offset + q * kX1, r, r).angle;
      EXPECT_NEAR(twist, 0.0, 1e-14) << "axis " << axis.transpose() << ", angle " << angle;
    }
}

// The twist after the increment `d` (per node Δu, then (a, b)).
double TwistAfter(const Eigen::Vector3d& x0,
                  const Eigen::Vector3d& x1,
                  Eigen::Matrix3d r0,
                  Eigen::Matrix3d r1,
                  const Dofs& d) {
  UpdateRotation(d.segment<2>(3), r0);
  UpdateRotation(d.segment<2>(8), r1);
  return EvaluateEdgeTwist(kReference, x0 + d.segment<3>(0), x1 + d.segment<3>(5), r0, r1).angle;
}

TEST(EdgeTwist, DerivativesMatchCentralDifferences) {
  // A general state: the edge moved, stretched and tilted, the directors
  // turned differently.
  const Eigen::Vector3d x0(0.1, 0.0, -0.05), x1(0.2, 1.1, 0.3);
  const Eigen::Matrix3d r0 = Turned({0.3, 0.9, 0.1}), r1 = Turned({-0.1, 1.4, 0.2});
  const EdgeTwist e = EvaluateEdgeTwist(kReference, x0, x1, r0, r1);
  const double h = 1e-4;
  double gradient_error = 0, hessian_error = 0;
  for (int k = 0; k < 10; ++k) {
    const Dofs dk = h * Dofs::Unit(k);
    const double g = (TwistAfter(x0, x1, r0, r1, dk) - TwistAfter(x0, x1, r0, r1, -dk)) / (2 * h);
    gradient_error = std::max(gradient_error, std::abs(g - e.gradient(k)));
    for (int l = 0; l < 10; ++l) {
      const Dofs dl = h * Dofs::Unit(l);
      const double hkl =
          (TwistAfter(x0, x1, r0, r1, dk + dl) - TwistAfter(x0, x1, r0, r1, dk - dl) -
           TwistAfter(x0, x1, r0, r1, dl - dk) + TwistAfter(x0, x1, r0, r1, -dk - dl)) /
          (4 * h * h);
      hessian_error = std::max(hessian_error, std::abs(hkl - e.hessian(k, l)));
    }
  }
  // Differences of step h are off by O(h²) ≈ 1e-8 here.
  std::printf("gradient off by %.2e, Hessian by %.2e (|H| = %.3f)\n",
              gradient_error,
              hessian_error,
              e.hessian.norm());
  EXPECT_GT(e.hessian.norm(), 0.1);
  EXPECT_LT(gradient_error, 1e-7);
  EXPECT_LT(hessian_error, 1e-6);
  EXPECT_LT((e.hessian - e.hessian.transpose()).norm(), 1e-14);
}

}  // namespace
}  // namespace drape
