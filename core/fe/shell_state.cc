#include "core/fe/shell_state.h"

#include <algorithm>

#include "core/mechanics/director.h"

namespace drape {

Eigen::Matrix<double, Eigen::Dynamic, 3> ShellState::Directors() const {
  Eigen::Matrix<double, Eigen::Dynamic, 3> t(NodeCount(), 3);
  for (int i = 0; i < NodeCount(); ++i) t.row(i) = rotations[i].col(2).transpose();
  return t;
}

bool IsFinite(const ShellState& state) {
  if (!state.positions.allFinite()) return false;
  for (const auto& r : state.rotations)
    if (!r.allFinite()) return false;
  for (const auto& o : state.obstacles)
    if (!o.rotation.allFinite() || !o.translation.allFinite()) return false;
  return true;
}

double MaxTranslation(const Eigen::VectorXd& increment) {
  double m = 0;
  for (int i = 0; i < increment.size() / kDofsPerNode; ++i)
    m = std::max(m, increment.segment<3>(kDofsPerNode * i).cwiseAbs().maxCoeff());
  return m;
}

void ApplyIncrement(const Eigen::VectorXd& increment, ShellState& state) {
  for (int i = 0; i < state.NodeCount(); ++i) {
    state.positions.row(i) += increment.segment<3>(kDofsPerNode * i).transpose();
    UpdateRotation(increment.segment<2>(kDofsPerNode * i + 3), state.rotations[i]);
  }
}

}  // namespace drape
