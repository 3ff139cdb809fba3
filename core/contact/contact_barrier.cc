#include "core/contact/contact_barrier.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace drape {

BarrierValue ClampedLogBarrier(double s, double s_hat) {
  BarrierValue b;
  if (s >= s_hat) return b;
  if (s <= 0) {
    b.value = b.first = std::numeric_limits<double>::infinity();
    b.first = -b.first;
    b.second = std::numeric_limits<double>::infinity();
    return b;
  }
  const double log = std::log(s / s_hat), gap = s - s_hat;
  b.value = -gap * gap * log;
  b.first = -2 * gap * log - gap * gap / s;
  b.second = -2 * log - 4 * gap / s + gap * gap / (s * s);
  return b;
}

PairPotential BarrierPotential(const DistanceDerivatives& d,
                               double offset,
                               double activation,
                               double stiffness) {
  PairPotential out;
  const double s_hat = 2 * offset * activation + activation * activation;
  const BarrierValue b = ClampedLogBarrier(d.squared - offset * offset, s_hat);
  if (b.value == 0) return out;
  out.energy = stiffness * b.value;
  out.gradient = stiffness * b.first * d.gradient;
  out.hessian = stiffness * (b.second * d.gradient * d.gradient.transpose() + b.first * d.hessian);
  return out;
}

namespace {

Eigen::Matrix3d Cross(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

double MollifierThreshold(const Eigen::Vector3d& rest_a0,
                          const Eigen::Vector3d& rest_a1,
                          const Eigen::Vector3d& rest_b0,
                          const Eigen::Vector3d& rest_b1) {
  return 1e-3 * (rest_a1 - rest_a0).squaredNorm() * (rest_b1 - rest_b0).squaredNorm();
}

PairPotential MollifiedEdgeEdgePotential(const DistanceDerivatives& d,
                                         const Eigen::Vector3d& a0,
                                         const Eigen::Vector3d& a1,
                                         const Eigen::Vector3d& b0,
                                         const Eigen::Vector3d& b1,
                                         double threshold,
                                         double offset,
                                         double activation,
                                         double stiffness) {
  PairPotential barrier = BarrierPotential(d, offset, activation, stiffness);
  const Eigen::Vector3d e0 = a1 - a0, e1 = b1 - b0, c = e0.cross(e1);
  const double x = c.squaredNorm();
  if (barrier.energy == 0 || x >= threshold) return barrier;
  const double r = x / threshold;
  const double m = (2 - r) * r, dm = (2 - 2 * r) / threshold, d2m = -2 / (threshold * threshold);
  // x and its derivatives in (e₀, e₁), then in (a0, a1, b0, b1): e₀ = a1 − a0,
  // e₁ = b1 − b0.
  Eigen::Matrix<double, 6, 1> gx;
  gx << 2 * e1.cross(c), 2 * c.cross(e0);
  Eigen::Matrix<double, 6, 6> hx;
  hx.block<3, 3>(0, 0) = -2 * Cross(e1) * Cross(e1);
  hx.block<3, 3>(0, 3) = 2 * (-Cross(c) + Cross(e1) * Cross(e0));
  hx.block<3, 3>(3, 0) = hx.block<3, 3>(0, 3).transpose();
  hx.block<3, 3>(3, 3) = -2 * Cross(e0) * Cross(e0);
  Eigen::Matrix<double, 12, 6> incidence = Eigen::Matrix<double, 12, 6>::Zero();
  incidence.block<3, 3>(0, 0) = -Eigen::Matrix3d::Identity();
  incidence.block<3, 3>(3, 0) = Eigen::Matrix3d::Identity();
  incidence.block<3, 3>(6, 3) = -Eigen::Matrix3d::Identity();
  incidence.block<3, 3>(9, 3) = Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, 12, 1> grad_x = incidence * gx;
  const Eigen::Matrix<double, 12, 12> hess_x = incidence * hx * incidence.transpose();

  PairPotential out;
  out.energy = m * barrier.energy;
  out.gradient = m * barrier.gradient + dm * barrier.energy * grad_x;
  out.hessian =
      m * barrier.hessian + d2m * barrier.energy * grad_x * grad_x.transpose() +
      dm * (grad_x * barrier.gradient.transpose() + barrier.gradient * grad_x.transpose()) +
      dm * barrier.energy * hess_x;
  return out;
}

}  // namespace drape
