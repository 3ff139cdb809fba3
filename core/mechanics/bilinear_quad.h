// Shape functions of the bilinear 4-node quadrilateral on [−1, 1]², nodes
// counter-clockwise from (−1, −1).
#pragma once

#include <Eigen/Core>

namespace drape {

inline constexpr double kQuadNodeXi[4] = {-1, 1, 1, -1};
inline constexpr double kQuadNodeEta[4] = {-1, -1, 1, 1};

// N_I(ξ, η) and, when asked, ∂N_I/∂(ξ, η).
inline void BilinearShape(double xi,
                          double eta,
                          Eigen::Vector4d& n,
                          Eigen::Matrix<double, 4, 2>* dn = nullptr) {
  for (int i = 0; i < 4; ++i) {
    n(i) = 0.25 * (1 + kQuadNodeXi[i] * xi) * (1 + kQuadNodeEta[i] * eta);
    if (dn) {
      (*dn)(i, 0) = 0.25 * kQuadNodeXi[i] * (1 + kQuadNodeEta[i] * eta);
      (*dn)(i, 1) = 0.25 * kQuadNodeEta[i] * (1 + kQuadNodeXi[i] * xi);
    }
  }
}

}  // namespace drape
