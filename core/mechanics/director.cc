#include "core/mechanics/director.h"

#include <Eigen/Geometry>
#include <cmath>

namespace drape {

Eigen::Matrix3d Skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d s;
  s << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return s;
}

Eigen::Matrix3d ExpRotation(const Eigen::Vector3d& w) {
  const double theta2 = w.squaredNorm();
  double a, b;  // sin θ / θ and (1 − cos θ) / θ²
  if (theta2 < 1e-8) {
    // Taylor series: the closed forms lose all digits as θ → 0.
    a = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    b = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
  } else {
    const double theta = std::sqrt(theta2);
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta2;
  }
  const Eigen::Matrix3d s = Skew(w);
  return Eigen::Matrix3d::Identity() + a * s + b * s * s;
}

namespace {

// The paper's formula, well conditioned for E₃·t ≥ 0 (1 + c ≥ 1).
Eigen::Matrix3d UpperHemisphere(const Eigen::Vector3d& t) {
  const double c = t.z();
  const Eigen::Vector3d k = Eigen::Vector3d::UnitZ().cross(t);
  return c * Eigen::Matrix3d::Identity() + Skew(k) + k * k.transpose() / (1.0 + c);
}

}  // namespace

Eigen::Matrix3d RotationFromDirector(const Eigen::Vector3d& t) {
  if (t.z() >= 0) return UpperHemisphere(t);
  // Below the equator 1 + c vanishes at t = −E₃ (0/0, NaN there and lost
  // digits near it). Turn by π about E₁ first: F = diag(1, −1, −1) takes E₃
  // to −E₃, so Λ = F Λ' with Λ' E₃ = F t, which lies in the upper half.
  const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
  return flip * UpperHemisphere(flip * t);
}

void UpdateRotation(const Eigen::Vector2d& increment, Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d w = increment.x() * rotation.col(0) + increment.y() * rotation.col(1);
  rotation = ExpRotation(w) * rotation;
}

Eigen::Matrix<double, 3, 2> DirectorTangent(const Eigen::Matrix3d& rotation) {
  Eigen::Matrix<double, 3, 2> t;
  t.col(0) = -rotation.col(1);
  t.col(1) = rotation.col(0);
  return t;
}

}  // namespace drape
