#include "core/solve/shell_state.h"

#include "core/mechanics/director.h"

namespace drape {

Eigen::Matrix<double, Eigen::Dynamic, 3> ShellState::Directors() const {
  Eigen::Matrix<double, Eigen::Dynamic, 3> t(NodeCount(), 3);
  for (int i = 0; i < NodeCount(); ++i) t.row(i) = rotations[i].col(2).transpose();
  return t;
}

void ApplyIncrement(const Eigen::VectorXd& increment, ShellState& state) {
  for (int i = 0; i < state.NodeCount(); ++i) {
    state.positions.row(i) += increment.segment<3>(kDofsPerNode * i).transpose();
    UpdateRotation(increment.segment<2>(kDofsPerNode * i + 3), state.rotations[i]);
  }
}

}  // namespace drape
