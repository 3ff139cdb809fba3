// Rigid motions of grippers along a stage's path, parameterised by the
// stage's λ ∈ [0, 1]: where a held point goes, how the hold turns, and how
// fast both change with λ (the continuation needs ∂u_p/∂λ).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/model/scene.h"

namespace drape {

// x(λ) = R(λ) (x₀ − c) + c + d(λ) for a point x₀ held at λ = 0.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();      // R(λ)
  Eigen::Vector3d center = Eigen::Vector3d::Zero();            // c
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();       // d(λ)
  Eigen::Vector3d angular_rate = Eigen::Vector3d::Zero();      // ω: dR/dλ = ω̂ R
  Eigen::Vector3d translation_rate = Eigen::Vector3d::Zero();  // dd/dλ

  Eigen::Vector3d Apply(const Eigen::Vector3d& x0) const {
    return rotation * (x0 - center) + center + translation;
  }
  // dx/dλ of the point that started at x0.
  Eigen::Vector3d Velocity(const Eigen::Vector3d& x0) const {
    return angular_rate.cross(rotation * (x0 - center)) + translation_rate;
  }
};

// The motion of `path` at λ (clamped to [0, 1]).
//  line      d = λ·by
//  arc       R = exp(λ θ â) about the axis through `center`
//  keyframes d through (0, 0), (1/n, p₁), …, (1, pₙ): piecewise linear, or
//            C¹ cubic Hermite with Catmull–Rom tangents ("smooth")
RigidMotion MotionAt(const Path& path, double lambda);

// Length of the path traced by a point x₀ (for step sizing and reports) [m].
double PathLength(const Path& path, const Eigen::Vector3d& x0);

}  // namespace drape
