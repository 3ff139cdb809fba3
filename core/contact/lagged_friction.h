// Lagged, smoothed Coulomb friction as a potential (Li et al., "Incremental
// Potential Contact", SIGGRAPH 2020, §5).
//
// Within a load increment the normal force λ_n and the tangent plane (basis
// T, 3×2 orthonormal) are held at their lagged values, so friction is the
// gradient of a potential in the node's position x alone:
//
//   D(x) = μ λ_n f₀(|u|),  u = Tᵀ (x − a),
//
// a the node's anchor (where its slip is measured from). f₀' = f₁ rises from
// 0 at u = 0 to the Coulomb limit 1 at |u| = ε (the slip at which a node
// turns from sticking to sliding, a length):
//
//   f₁(y) = 2y/ε − y²/ε²  (y < ε),  1 (y ≥ ε),
//
// and its Hessian μ λ_n T [f₁' ûûᵀ + (f₁/y)(I − ûûᵀ)] Tᵀ is positive
// semidefinite everywhere, because f₁ never falls. The solver re-lags λ_n
// and T until they stop changing (core/solve/contact_augmentation.h), which
// makes the lagged force Coulomb's.
#pragma once

#include <Eigen/Core>

namespace drape {

// f₀(y) = y²/ε − y³/(3ε²) + ε/3 below ε, y above (C² at ε, f₀(0) = ε/3).
double FrictionSlipPotential(double y, double epsilon);
// f₁ = f₀' ∈ [0, 1]: the share of the Coulomb limit mobilised at slip y.
double FrictionMobilised(double y, double epsilon);

struct FrictionResponse {
  double energy = 0;                                    // μ λ_n f₀(|u|) [J]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();      // −∂D/∂x [N]
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();  // ∂²D/∂x² [N/m]
  double slip = 0;                                      // |u| [m]
  double mobilised = 0;                                 // f₁(|u|)
};

// The friction on a node at `x` with anchor `anchor`, lagged tangent basis
// `basis` (orthonormal columns) and lagged limit `limit` = μ λ_n [N].
FrictionResponse EvaluateFriction(const Eigen::Vector3d& x,
                                  const Eigen::Vector3d& anchor,
                                  const Eigen::Matrix<double, 3, 2>& basis,
                                  double limit,
                                  double epsilon);

// An orthonormal basis of the plane normal to the unit vector `n`.
Eigen::Matrix<double, 3, 2> TangentBasis(const Eigen::Vector3d& n);

}  // namespace drape
