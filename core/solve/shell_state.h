// The configuration of the shell at one instant: per node a midsurface
// position φ and an orientation Λ (director t = Λ E₃).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace drape {

constexpr int kDofsPerNode = 5;  // Δu (3) and the rotation increment (a, b) in the tangent basis

struct ShellState {
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;  // #nodes × 3 [m]
  std::vector<Eigen::Matrix3d> rotations;              // Λ per node

  int NodeCount() const { return static_cast<int>(positions.rows()); }
  Eigen::Vector3d Director(int node) const { return rotations[node].col(2); }
  Eigen::Matrix<double, Eigen::Dynamic, 3> Directors() const;
};

// Adds a full increment (5 values per node, node-major): φ += Δu and
// Λ ← exp(ŵ) Λ with w = a g₁ + b g₂.
void ApplyIncrement(const Eigen::VectorXd& increment, ShellState& state);

}  // namespace drape
