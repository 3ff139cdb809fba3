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

#include "core/mechanics/primitive_distance.h"

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

}  // namespace drape
