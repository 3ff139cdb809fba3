// Self-contact of the fabric (issue 17): the barrier potential
// (core/contact/contact_barrier.h) summed over every point–triangle and
// edge–edge pair of its mid-surface that is within reach and more than the
// exclusion apart at rest (core/contact/self_proximity.h), acting on the
// nodes' translations; and the collision-free fraction of a step
// (core/contact/additive_ccd.h). The pairs within reach are kept in a
// list of those within a wider radius (a Verlet list), searched again only
// once some node has moved far enough since that a pair outside the list
// could have come within reach: a part whose layers stay apart pays one
// broad phase per few iterations, not per evaluation.
#pragma once

#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

#include "core/contact/self_proximity.h"
#include "core/model/mesh.h"

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
  int active_pairs = 0;  // pairs inside the barrier's band
  // Σ over pairs of the force one side exerts on the other (on the point of
  // a point–triangle pair, on the first edge of an edge–edge pair) [N].
  double force = 0;
  // The smallest distance among the pairs evaluated [m]; every other pair
  // is farther apart than offset + activation.
  double smallest_distance = INFINITY;
};

class SelfContact {
 public:
  SelfContact(const Mesh& mesh, const SelfContactSettings& settings);

  // Not thread-safe: it updates the list of pairs.
  // Not const: it renews the kept pair list when x has moved beyond it.
  SelfContactEvaluation Evaluate(const Positions& x, bool with_hessian);

  // The largest t ∈ [0, 1] such that x + τ dx keeps every pair outside the
  // offset for τ ≤ t (conservatively: it stops short).
  double StepBound(const Positions& x, const Positions& dx) const;

  // The node pairs of every candidate pair within `reach` [m] (each pair
  // once, smaller node first): what the tangent's pattern must couple.
  std::vector<std::pair<int, int>> NodePairs(const Positions& x, double reach) const;

  const SelfContactSettings& settings() const { return settings_; }

 private:
  // Whether the list still holds every pair that can come within reach
  // when the nodes are at x and move further by motions of spread `motion`
  // [m] (MotionSpread).
  bool ListCovers(const Positions& x, double motion) const;

  SelfContactSettings settings_;
  // The list's radius beyond the reach [m]: twice the reach or an element,
  // whichever is larger.
  double list_margin_;
  Positions list_positions_;
  ProximityPairs list_;
  SelfProximity proximity_;
  Positions rest_;
};

}  // namespace drape
