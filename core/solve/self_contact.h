// Self-contact of the fabric (issue 17): the barrier potential
// (core/mechanics/contact_barrier.h) summed over every point–triangle and
// edge–edge pair of its mid-surface that is within reach and more than the
// exclusion apart at rest (core/solve/self_proximity.h), acting on the
// nodes' translations; and the collision-free fraction of a step
// (core/mechanics/additive_ccd.h). Not yet part of the equilibrium system.
#pragma once

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

#include "core/model/mesh.h"
#include "core/solve/self_proximity.h"

namespace drape {

struct SelfContactSettings {
  double offset = 0;      // ξ: the thickness the layers keep apart [m]
  double activation = 0;  // d̂: the barrier acts while d < ξ + d̂ [m]
  double stiffness = 0;   // κ [J]
  double exclusion = 0;   // pairs closer than this at rest never touch [m]
};

struct SelfContactEvaluation {
  double energy = 0;         // Σ κ b [J]
  Eigen::VectorXd gradient;  // ∂E/∂x, 3 per node (x, y, z) [N]
  // ∂²E/∂x² as 12 × 12 blocks on four nodes each (a node may repeat).
  std::vector<std::array<int, 4>> block_nodes;
  std::vector<Eigen::Matrix<double, 12, 12>> blocks;
  int active_pairs = 0;                 // pairs inside the barrier's band
  double smallest_distance = INFINITY;  // among pairs within reach [m]
};

class SelfContact {
 public:
  SelfContact(const Mesh& mesh, const SelfContactSettings& settings);

  SelfContactEvaluation Evaluate(const Positions& x, bool with_hessian) const;

  // The largest t ∈ [0, 1] such that x + τ dx keeps every pair outside the
  // offset for τ ≤ t (conservatively: it stops short).
  double StepBound(const Positions& x, const Positions& dx) const;

  // The node pairs of every candidate pair within `reach` [m] (each pair
  // once, smaller node first): what the tangent's pattern must couple.
  std::vector<std::pair<int, int>> NodePairs(const Positions& x, double reach) const;

  const SelfContactSettings& settings() const { return settings_; }

 private:
  SelfContactSettings settings_;
  SelfProximity proximity_;
  Positions rest_;
};

}  // namespace drape
