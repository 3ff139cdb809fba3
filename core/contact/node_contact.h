// Penalty contact of the fabric's nodes with rigid obstacles (DESIGN.md §8).
//
// A node at signed distance d from an obstacle has the gap g = d − h/2 (the
// fabric's surface is half a thickness from its midsurface). For g < 0 the
// energy is ½ k A g², with k the penalty per area and A the node's share of
// the reference area, so the penalty is mesh independent: the force is
// −k A g n and the tangent k A (n nᵀ + g ∇∇d). With an augmented-Lagrangian
// multiplier m the normal force is f_n = m − k A g (≥ 0), and the tangent
// k A n nᵀ − f_n ∇∇d.
//
// Coulomb friction (μ > 0), regularised: the tangential slip s of a node
// from its anchor (where the last converged step left it, less the slip it
// carried) gives the force −μ f_n s / √(|s|² + ε²), ε = μ f_n / (k A): a
// stiff spring for small slip, the Coulomb limit for large, smooth in
// between. A node loaded below the limit creeps by less than ε and stays; one
// loaded above it slides. Only the elastic part of the slip (at most 3ε)
// carries over to the next step, so a node that slid drags its anchor along
// and its friction turns round when it moves back.
//
// Scenes held only by contact (a sheet on a frictionless table, a strip hung
// over a rod) have rigid motions that nothing resists; for those, weak springs
// tie each node to where it was at the end of the last converged step
// (Abaqus's "contact stabilisation"): their force vanishes as the steps
// settle, and the largest one is reported so the user can judge it.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include "core/contact/contact_report.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/fe/stage_loading.h"
#include "core/model/obstacle_geometry.h"

namespace drape {

struct NamedObstacle {
  std::string name;
  std::unique_ptr<ObstacleGeometry> geometry;
};

class NodeContact {
 public:
  // `penalty`: k per area [N/m³]; `stabilization`: spring per node [N/m], 0
  // for none.
  NodeContact(const ShellModel& model,
              std::vector<NamedObstacle> obstacles,
              double penalty,
              double stabilization,
              double friction = 0.0);

  // Adds ∂E/∂x of contact and stabilisation to `internal` (5 per node) and,
  // with `blocks`, each node's 3×3 translational tangent block (row-major).
  // With `velocity` and `rate`, adds the contact tangent times the
  // prescribed velocity (the λ-rate of the force at moving nodes).
  void Add(const ShellState& state,
           Eigen::VectorXd& internal,
           std::vector<Eigen::Matrix3d>* blocks,
           const Eigen::VectorXd* velocity,
           Eigen::VectorXd* rate) const;

  // The energy whose gradient Add's normal and stabilisation forces are [J]:
  // ½ k A (m/(kA) − g)² per node pressed in (m the multiplier), ½ s |x − a|²
  // per spring. Friction dissipates; it has none.
  double Energy(const ShellState& state) const;

  // The stabilisation springs and the friction anchors start again from
  // `state` (a converged step).
  void Commit(const ShellState& state);
  // `held[i]`: node i's position is prescribed (a support or a gripper); it
  // gets no spring, which would resist nothing and only add its force to
  // the node's reaction. Empty: every node gets one.
  void SetStabilization(double per_node, std::vector<bool> held = {}) {
    stabilization_ = per_node;
    held_ = std::move(held);
  }
  const std::vector<bool>& stabilization_held() const { return held_; }

  // Augmented Lagrangian (Uzawa): each node's multiplier takes its present
  // normal force, so the next equilibrium needs that much less penetration.
  // Repeated, the penetration falls geometrically without a stiffer penalty.
  void Augment(const ShellState& state);
  const std::vector<double>& multipliers() const { return multiplier_; }
  void SetMultipliers(std::vector<double> m) { multiplier_ = std::move(m); }

  // Adds ∂(∂E/∂x)/∂λ of contact at fixed nodes while obstacles move.
  void AddObstacleRate(const ShellState& state,
                       const std::vector<ObstacleMotion>& motions,
                       Eigen::VectorXd& rate) const;

  ContactReport Report(const ShellState& state) const;
  // Nodes deeper than `depth` inside an obstacle, deepest first: "node N is
  // X mm inside 'table'" lines, for the start of a run.
  // `among`: only these nodes (empty: every node).
  std::vector<std::string> Penetrations(const ShellState& state,
                                        double depth,
                                        const std::vector<int>& among = {}) const;

  double penalty() const { return penalty_; }
  double stabilization() const { return stabilization_; }
  double half_thickness() const { return half_thickness_; }
  double friction() const { return friction_; }
  const std::vector<double>& nodal_area() const { return area_; }

 private:
  // Calls f(node, obstacle, g, query) for every node in contact.
  template <typename F>
  void ForEachContact(const ShellState& state, F&& f) const;

  // The force obstacle `o` exerts on node `i` (normal and friction), its
  // normal part's magnitude, and the tangent −∂force/∂x (symmetric part).
  struct NodeResponse {
    Eigen::Vector3d force;
    double normal_force = 0;
    Eigen::Matrix3d stiffness;
  };
  static ObstaclePlacement PlacementOf(const ShellState& state, int o);
  // Obstacle o's distance at world x, with it where `state` has placed it.
  DistanceQuery Query(const ShellState& state, int o, const Eigen::Vector3d& x) const;
  Eigen::Vector3d FrictionAnchor(const ShellState& state, int i, int o) const;
  NodeResponse Respond(const ShellState& state,
                       int i,
                       int o,
                       double g,
                       const DistanceQuery& q,
                       const Eigen::Vector3d& x) const;

  std::vector<NamedObstacle> obstacles_;
  std::vector<double> area_;  // tributary reference area per node [m²]
  double penalty_;
  double stabilization_;
  std::vector<bool> held_;  // nodes without a spring
  double half_thickness_;
  double friction_;
  Eigen::MatrixXd anchors_;  // node positions of the last converged step
  // Friction anchors per node and obstacle (index i·obstacles + o); NaN
  // where the node was not in contact at the last commit.
  std::vector<Eigen::Vector3d> stick_;
  // Augmented-Lagrangian normal force per node and obstacle [N] (same index).
  std::vector<double> multiplier_;
};

// k per area for `contact.penalty: "auto"`: the membrane stiffness of the
// section over the square of the mean element size, E h / ((1 − ν²) ℓ²)
// [N/m³]. A node
// then pushes into an obstacle about as hard as it pulls on its neighbours,
// so the penetration under a load p is p ℓ² / (E h) while the tangent keeps
// the conditioning it had without contact.
double AutoPenalty(const ShellModel& model);

// The stabilisation springs of `contact` (may be null) off for this object's
// lifetime and back on after: they hold the nodes where the last step left
// them, and a part that snaps must not land propped on them.
class StabilizationOff {
 public:
  explicit StabilizationOff(NodeContact* contact)
      : contact_(contact),
        per_node_(contact ? contact->stabilization() : 0.0),
        held_(contact ? contact->stabilization_held() : std::vector<bool>{}) {
    if (contact_) contact_->SetStabilization(0.0, held_);
  }
  ~StabilizationOff() {
    if (contact_) contact_->SetStabilization(per_node_, held_);
  }
  StabilizationOff(const StabilizationOff&) = delete;
  StabilizationOff& operator=(const StabilizationOff&) = delete;

 private:
  NodeContact* contact_;
  double per_node_;
  std::vector<bool> held_;
};

}  // namespace drape
