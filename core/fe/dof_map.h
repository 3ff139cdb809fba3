// Numbering of the free degrees of freedom. Every node has 5 (Δu and the two
// rotation components); supports, grippers and clamps fix some of them, and
// the linear system holds only the rest.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "core/fe/shell_state.h"
#include "core/model/scene.h"

namespace drape {

class DofMap {
 public:
  explicit DofMap(int node_count);

  // `position` fixes Δu; `clamp` fixes Δu and the rotation.
  void FixNode(int node, Fixity fixity);
  // One DOF alone (e.g. a node held in one direction only).
  void FixDof(int dof);

  int DofCount() const { return static_cast<int>(free_index_.size()); }
  int FreeCount() const { return free_count_; }
  // Index in the free system, or −1 for a fixed DOF.
  int Free(int dof) const { return free_index_[dof]; }
  bool IsFixed(int dof) const { return free_index_[dof] < 0; }

  // Free entries of a full vector, and back (fixed entries zero).
  Eigen::VectorXd Restrict(const Eigen::VectorXd& full) const;
  Eigen::VectorXd Expand(const Eigen::VectorXd& free) const;

  friend bool operator==(const DofMap&, const DofMap&) = default;

 private:
  void Renumber();

  std::vector<int> free_index_;
  int free_count_ = 0;
};

}  // namespace drape
