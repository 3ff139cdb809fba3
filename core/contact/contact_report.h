// What contact does in a converged state, as a step reports it.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace drape {

// A node's friction: none (no contact or no friction), sticking (below its
// Coulomb limit) or sliding (at it).
enum class SlipState : unsigned char { kNone = 0, kSticking = 1, kSliding = 2 };

// What contact does in a state (scenes with obstacles).
struct ContactReport {
  int nodes = 0;                                    // nodes in contact
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // obstacles on the fabric [N]
  double max_penetration = 0;                       // largest −g [m], ≥ 0
  // With the "auto" penalty: the penetration the augmented-Lagrangian passes
  // hold (0: no target, a penalty the user set), the passes this step took,
  // and why they stopped short of the target ("" when it was met).
  double penetration_target = 0;  // [m]
  int augmentation_passes = 0;
  std::string augmentation_shortfall;
  // The stabilisation springs of a scene held only by contact (zero when off).
  Eigen::Vector3d stabilization_force = Eigen::Vector3d::Zero();  // Σ [N]
  double max_stabilization_force = 0;                             // largest nodal [N]
  std::vector<double> pressure;  // per node: contact force / tributary area [Pa]
  // Friction: the obstacles' tangential force on the fabric [N] (part of
  // `force`), the nodes sticking and sliding, and each node's state.
  bool with_friction = false;  // μ > 0
  Eigen::Vector3d friction_force = Eigen::Vector3d::Zero();
  int sticking = 0;
  int sliding = 0;
  std::vector<SlipState> friction;
};

}  // namespace drape
