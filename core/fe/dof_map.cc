#include "core/fe/dof_map.h"

namespace drape {

DofMap::DofMap(int node_count) : free_index_(kDofsPerNode * node_count, 0) {
  Renumber();
}

void DofMap::FixNode(int node, Fixity fixity) {
  const int count = fixity == Fixity::kClamp ? kDofsPerNode : 3;
  for (int k = 0; k < count; ++k) free_index_[kDofsPerNode * node + k] = -1;
  Renumber();
}

void DofMap::FixDof(int dof) {
  free_index_[dof] = -1;
  Renumber();
}

void DofMap::Renumber() {
  free_count_ = 0;
  for (int& index : free_index_)
    if (index >= 0) index = free_count_++;
}

Eigen::VectorXd DofMap::Restrict(const Eigen::VectorXd& full) const {
  Eigen::VectorXd free(free_count_);
  for (int d = 0; d < DofCount(); ++d)
    if (free_index_[d] >= 0) free(free_index_[d]) = full(d);
  return free;
}

Eigen::VectorXd DofMap::Expand(const Eigen::VectorXd& free) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(DofCount());
  for (int d = 0; d < DofCount(); ++d)
    if (free_index_[d] >= 0) full(d) = free(free_index_[d]);
  return full;
}

}  // namespace drape
