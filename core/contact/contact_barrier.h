// The potential that keeps two parts of the fabric a thickness apart
// (issue 17): C-IPC's clamped log barrier (Li, Kaufman, Jiang et al.,
// SIGGRAPH 2021) on the squared distance beyond an offset ξ,
//
//   b(s) = −(s − ŝ)² ln(s / ŝ)  for 0 < s < ŝ,  0 for s ≥ ŝ,
//   s = d² − ξ²,  ŝ = 2ξd̂ + d̂²,
//
// active while d < ξ + d̂, infinite at d = ξ, and C² where it switches on. A
// potential, so the contact forces and tangent are consistent and
// symmetric; the Hessian is kept exact (not projected), so the tangent's
// inertia still tells stable from unstable.
#pragma once

#include <Eigen/Core>

#include "core/geometry/primitive_distance.h"

namespace drape {

struct BarrierValue {
  double value = 0, first = 0, second = 0;  // b, db/ds, d²b/ds²
};

// b(s) and its derivatives; s ≤ 0 (at or inside the offset) gives +∞.
BarrierValue ClampedLogBarrier(double s, double s_hat);

struct PairPotential {
  double energy = 0;
  Eigen::Matrix<double, 12, 1> gradient = Eigen::Matrix<double, 12, 1>::Zero();
  Eigen::Matrix<double, 12, 12> hessian = Eigen::Matrix<double, 12, 12>::Zero();
};

// κ b(d² − ξ², 2ξd̂ + d̂²) of a pair whose squared distance and its
// derivatives are `d`: `offset` ξ [m], `activation` d̂ [m], `stiffness` κ.
PairPotential BarrierPotential(const DistanceDerivatives& d,
                               double offset,
                               double activation,
                               double stiffness);

// The edge–edge mollifier (IPC, Li et al. 2020, §4.3): nearly parallel
// edges (x = |e₀ × e₁|² below ε_x = 10⁻³ |e₀|²|e₁|² at rest) have a
// distance whose closest points jump; m(x) = (2 − x/ε_x) x/ε_x takes their
// barrier smoothly to zero as the edges turn parallel, where a point–
// triangle pair of the same faces carries the contact instead.
double MollifierThreshold(const Eigen::Vector3d& rest_a0,
                          const Eigen::Vector3d& rest_a1,
                          const Eigen::Vector3d& rest_b0,
                          const Eigen::Vector3d& rest_b1);

// m(x) κ b of an edge–edge pair (a0, a1), (b0, b1) with squared distance
// derivatives `d` (EdgeEdgeDerivatives), and its gradient and Hessian.
PairPotential MollifiedEdgeEdgePotential(const DistanceDerivatives& d,
                                         const Eigen::Vector3d& a0,
                                         const Eigen::Vector3d& a1,
                                         const Eigen::Vector3d& b0,
                                         const Eigen::Vector3d& b1,
                                         double threshold,
                                         double offset,
                                         double activation,
                                         double stiffness);

}  // namespace drape
