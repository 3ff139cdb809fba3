// Stress-resultant constitutive law of the shell section: n = D_m ε,
// q = D_s γ (linear elastic), and m = D_b κ or, for a nonlinear bending law,
// m = ∂W/∂κ; all per unit reference length, in the material frame of the
// reference surface (e₁ = warp), Voigt order (11, 22, 12) with engineering
// shear (2ε₁₂, 2κ₁₂).
#pragma once

#include <Eigen/Core>

#include <memory>

#include "core/mechanics/bending_friction.h"
#include "core/mechanics/plate_bending_law.h"

namespace drape {

struct ShellSection {
  Eigen::Matrix3d membrane = Eigen::Matrix3d::Zero();  // D_m = h C [N/m]
  // D_b [N·m]: the bending tangent of a linear law, the initial tangent of a
  // nonlinear one.
  Eigen::Matrix3d bending = Eigen::Matrix3d::Zero();
  Eigen::Matrix2d shear = Eigen::Matrix2d::Zero();  // D_s = κₛ G h I [N/m]
  // Set for a nonlinear bending law, which then replaces D_b κ.
  std::shared_ptr<const PlateBendingLaw> bending_law;
  // Set for bending hysteresis (KES 2HB), whose moment joins the law's.
  std::shared_ptr<const BendingFriction> friction;
};

// Isotropic section: E [Pa], ν, thickness h [m]. `bending_rigidity` B [N·m]
// (per unit width, as a strip test measures it) replaces E h³/12 when > 0;
// κₛ = 5/6.
ShellSection IsotropicSection(double youngs_modulus,
                              double poisson_ratio,
                              double thickness,
                              double bending_rigidity = 0.0);

// Plane-stress orthotropic stiffness in the material axes (1 = warp):
// C = [[E₁, ν₂₁E₁, 0], [ν₁₂E₂, E₂, 0], [0, 0, G₁₂(1 − ν₁₂ν₂₁)]] / (1 − ν₁₂ν₂₁),
// ν₂₁ = ν₁₂E₂/E₁ (symmetric). E₁, E₂, G₁₂ [Pa].
Eigen::Matrix3d OrthotropicStiffness(double e1, double e2, double nu12, double g12);

// Membrane D_m = h C(E₁, E₂, ν₁₂, G₁₂); bending from `bending` (a linear
// D_b, or the initial tangent of `bending_law` when that is set); transverse
// shear κₛ G_t h with G_t = √(E₁E₂)/2(1 + ν₁₂), a stiff Reissner–Mindlin
// constraint rather than a fabric property (woven fabrics' in-plane G₁₂ is
// far lower and would let the directors shear away from the normal).
ShellSection OrthotropicSection(double e1, double e2, double nu12, double g12, double thickness);

}  // namespace drape
