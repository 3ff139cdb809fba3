#include "core/contact/lagged_friction.h"

#include <Eigen/Geometry>

#include <cmath>

namespace drape {

double FrictionSlipPotential(double y, double epsilon) {
  if (y >= epsilon) return y;
  return y * y / epsilon - y * y * y / (3 * epsilon * epsilon) + epsilon / 3;
}

double FrictionMobilised(double y, double epsilon) {
  if (y >= epsilon) return 1.0;
  return 2 * y / epsilon - y * y / (epsilon * epsilon);
}

FrictionResponse EvaluateFriction(const Eigen::Vector3d& x,
                                  const Eigen::Vector3d& anchor,
                                  const Eigen::Matrix<double, 3, 2>& basis,
                                  double limit,
                                  double epsilon) {
  FrictionResponse r;
  const Eigen::Vector2d u = basis.transpose() * (x - anchor);
  const double y = u.norm();
  r.slip = y;
  r.mobilised = FrictionMobilised(y, epsilon);
  r.energy = limit * FrictionSlipPotential(y, epsilon);
  // f₁/y and f₁' with their common limit 2/ε at y = 0 (no division by a
  // vanishing slip).
  const double over_y = y >= epsilon ? 1.0 / y : (2 - y / epsilon) / epsilon;
  const double slope = y >= epsilon ? 0.0 : 2 * (1 - y / epsilon) / epsilon;
  r.force = -limit * over_y * (basis * u);
  Eigen::Matrix2d h = over_y * Eigen::Matrix2d::Identity();
  if (y > 0) {
    const Eigen::Vector2d unit = u / y;
    h += (slope - over_y) * unit * unit.transpose();
  }
  r.stiffness = limit * basis * h * basis.transpose();
  return r;
}

Eigen::Matrix<double, 3, 2> TangentBasis(const Eigen::Vector3d& n) {
  // The coordinate axis least aligned with n, crossed with n.
  Eigen::Index axis;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::Unit(axis)).normalized();
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = t1;
  basis.col(1) = n.cross(t1);
  return basis;
}

}  // namespace drape
