#include "core/solve/element_fields.h"

#include <algorithm>
#include <cmath>

namespace drape {

double MaxPrincipalCurvature(const ShellModel& model, const ShellState& state) {
  double largest = 0;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    NodeColumns x, t;
    for (int k = 0; k < 4; ++k) {
      const int node = model.mesh.quads(e, k);
      x.col(k) = state.positions.row(node).transpose();
      t.col(k) = state.Director(node);
    }
    for (const Eigen::Vector3d& k : BendingStrains(model.elements[e], x, t)) {
      // Principal values of [[κ₁₁, κ₁₂], [κ₁₂, κ₂₂]]: mean ± radius.
      const double mean = 0.5 * (k(0) + k(1));
      const double radius = std::hypot(0.5 * (k(0) - k(1)), 0.5 * k(2));
      largest = std::max(largest, std::abs(mean) + radius);
    }
  }
  return largest;
}

}  // namespace drape
