#include "core/mechanics/shell_section.h"

#include <cmath>

namespace drape {

ShellSection IsotropicSection(double youngs_modulus,
                              double poisson_ratio,
                              double thickness,
                              double bending_rigidity) {
  const double nu = poisson_ratio;
  // Plane-stress C / E.
  Eigen::Matrix3d c;
  c << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  c /= (1 - nu * nu);
  const double h = thickness;
  const double strip_rigidity =
      bending_rigidity > 0 ? bending_rigidity : youngs_modulus * h * h * h / 12.0;
  const double shear_modulus = youngs_modulus / (2 * (1 + nu));
  ShellSection s;
  s.membrane = youngs_modulus * h * c;
  s.bending = strip_rigidity * c;
  s.shear = (5.0 / 6.0) * shear_modulus * h * Eigen::Matrix2d::Identity();
  return s;
}

Eigen::Matrix3d OrthotropicStiffness(double e1, double e2, double nu12, double g12) {
  const double nu21 = nu12 * e2 / e1;
  const double det = 1 - nu12 * nu21;
  Eigen::Matrix3d c;
  c << e1, nu21 * e1, 0, nu12 * e2, e2, 0, 0, 0, g12 * det;
  return c / det;
}

ShellSection OrthotropicSection(double e1, double e2, double nu12, double g12, double thickness) {
  ShellSection s;
  s.membrane = thickness * OrthotropicStiffness(e1, e2, nu12, g12);
  const double transverse_shear = std::sqrt(e1 * e2) / (2 * (1 + nu12));
  s.shear = (5.0 / 6.0) * transverse_shear * thickness * Eigen::Matrix2d::Identity();
  return s;
}

}  // namespace drape
