// The configuration of the shell at one instant: per node a midsurface
// position φ and an orientation Λ (director t = Λ E₃).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "core/mechanics/bending_friction.h"

namespace drape {

constexpr int kDofsPerNode = 5;  // Δu (3) and the rotation increment (a, b) in the tangent basis

// Where a rigid obstacle is: world x = R x_scene + t, x_scene a point of the
// obstacle as the scene gives it. Stages may carry obstacles along paths.
struct ObstaclePlacement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d ToWorld(const Eigen::Vector3d& x) const { return rotation * x + translation; }
  Eigen::Vector3d ToScene(const Eigen::Vector3d& x) const {
    return rotation.transpose() * (x - translation);
  }
  bool IsIdentity() const { return rotation.isIdentity(0.0) && translation.isZero(0.0); }
};

struct ShellState {
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;  // #nodes × 3 [m]
  std::vector<Eigen::Matrix3d> rotations;              // Λ per node
  // One per scene obstacle (empty: every obstacle where the scene put it).
  std::vector<ObstaclePlacement> obstacles;
  // The point loads' factor here (StageLoading::Place sets it): the moments
  // about loaded edges are potentials, so the system's energy scales with it.
  double load_factor = 0;
  // With bending hysteresis: per element, the slip curvatures its Gauss
  // points had at the last accepted step (CommitBendingSlip); empty: none yet.
  // Part of the state, so that a step restarted from a kept state restarts
  // from its history too.
  std::vector<ElementSlip> bending_slip;

  int NodeCount() const { return static_cast<int>(positions.rows()); }
  Eigen::Vector3d Director(int node) const { return rotations[node].col(2); }
  Eigen::Matrix<double, Eigen::Dynamic, 3> Directors() const;
};

// Every position and rotation entry finite (obstacles too).
bool IsFinite(const ShellState& state);

// The largest translation component of a full increment (5 per node) [m].
double MaxTranslation(const Eigen::VectorXd& increment);

// Adds a full increment (5 values per node, node-major): φ += Δu and
// Λ ← exp(ŵ) Λ with w = a g₁ + b g₂.
void ApplyIncrement(const Eigen::VectorXd& increment, ShellState& state);

}  // namespace drape
