// Stress-resultant constitutive law of the shell section (linear elastic):
// n = D_m ε, m = D_b κ, q = D_s γ, all per unit reference length, in the local
// Cartesian frame of the reference surface, Voigt order (11, 22, 12) with
// engineering shear (2ε₁₂, 2κ₁₂).
#pragma once

#include <Eigen/Core>

namespace drape {

struct ShellSection {
  Eigen::Matrix3d membrane = Eigen::Matrix3d::Zero();  // D_m = h C [N/m]
  Eigen::Matrix3d bending = Eigen::Matrix3d::Zero();   // D_b = h³/12 C [N·m]
  Eigen::Matrix2d shear = Eigen::Matrix2d::Zero();     // D_s = κₛ G h I [N/m]
};

// Isotropic section: E [Pa], ν, thickness h [m]. `bending_rigidity` B [N·m]
// (per unit width, as a strip test measures it) replaces E h³/12 when > 0;
// κₛ = 5/6.
ShellSection IsotropicSection(double youngs_modulus,
                              double poisson_ratio,
                              double thickness,
                              double bending_rigidity = 0.0);

}  // namespace drape
