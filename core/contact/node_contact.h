// Contact of the fabric's nodes with rigid obstacles (DESIGN.md §8).
//
// A node at signed distance d from an obstacle has the gap g = d − h/2 (the
// fabric's surface is half a thickness from its midsurface). Its normal
// force f_n(g) ≥ 0 acts along n = ∇d, with the tangent k n nᵀ − f_n ∇∇d
// (k = −df_n/dg), by one of two laws:
//
// - Penalty: for g < 0 the energy is ½ k A g², with k the penalty per area
//   and A the node's share of the reference area, so the penalty is mesh
//   independent. With an augmented-Lagrangian multiplier m the normal force
//   is f_n = m − k A g. A node may sit a little inside (the passes shrink
//   it), and the energy is only C¹ where contact starts.
// - Barrier: the clamped log barrier κ A b(g) of contact_barrier.h over the
//   band 0 < g < d̂: C² where it starts, infinite at g = 0, so no node's
//   surface ever reaches an obstacle. Every update is cut short where a node
//   would close 90 % of its gap (StepBound).
//
// Coulomb friction (μ > 0): the lagged potential of lagged_friction.h. Each
// node in contact keeps its normal force, tangent plane and anchor from the
// last converged step (its lag); within a step friction is then a potential
// in the node's position, with a symmetric, positive semidefinite tangent,
// the same for path following and for energy minimisation. Re-lagging at
// the converged state (Relag) makes the normal force Coulomb's. The anchor
// keeps the node's elastic slip (at most ε, where friction turns from stick
// to slide) from step to step, so a node whose friction balances its load
// stays put in the next step, and one that slid turns its friction round
// once it moves back by 2ε, as Coulomb friction does.
//
// Scenes held only by contact (a sheet on a frictionless table, a strip hung
// over a rod) have rigid motions that nothing resists; for those, weak springs
// tie each node to where it was at the end of the last converged step
// (Abaqus's "contact stabilisation"): their force vanishes as the steps
// settle, and the largest one is reported so the user can judge it.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/contact/contact_report.h"
#include "core/contact/lagged_friction.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/fe/stage_loading.h"
#include "core/model/obstacle_geometry.h"

namespace drape {

// A node's friction as the last converged step (or a re-lag) left it, in
// the obstacle's own frame (it moves with the obstacle).
struct FrictionLag {
  double normal_force = 0;  // λ_n [N]; 0: no friction
  Eigen::Matrix<double, 3, 2> basis = Eigen::Matrix<double, 3, 2>::Zero();
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
};

struct NamedObstacle {
  std::string name;
  std::unique_ptr<ObstacleGeometry> geometry;
};

// How an obstacle pushes: a penalty (barrier_distance 0) or the barrier.
struct NormalLaw {
  double penalty = 0;            // k per area [N/m³]
  double barrier_distance = 0;   // d̂ [m]; 0: the penalty law
  double barrier_stiffness = 0;  // κ per area [N/m³]
};

// The node nearest to an obstacle: its gap g = d − h/2 [m] (+∞ without
// obstacles).
struct ClosestNode {
  double gap = INFINITY;
  int node = -1;
  int obstacle = -1;
};

class NodeContact {
 public:
  // `stabilization`: spring per node [N/m], 0 for none; `friction`: μ;
  // `friction_slip`: ε [m], the slip at which a node turns from sticking to
  // sliding (0: DefaultFrictionSlip).
  NodeContact(const ShellModel& model,
              std::vector<NamedObstacle> obstacles,
              const NormalLaw& law,
              double stabilization,
              double friction = 0.0,
              double friction_slip = 0.0);

  // The largest t ∈ [0, 1] for which the nodes moved from `state` by t dx
  // (one row per node) keep at least a tenth of their gap to every obstacle
  // (1 under the penalty law). Exact for convex obstacles, whose distance
  // is convex outside them; for a mesh the step's end is checked (and
  // halved until it keeps the tenth): a node cannot then pass through a
  // part of the form thinner than one update.
  double StepBound(const ShellState& state, const Eigen::MatrixX3d& dx) const;
  bool HasBarrier() const { return law_.barrier_distance > 0; }
  ClosestNode Closest(const ShellState& state) const;

  // Adds ∂E/∂x of contact and stabilisation to `internal` (5 per node) and,
  // with `blocks`, each node's 3×3 translational tangent block (row-major).
  // With `velocity` and `rate`, adds the contact tangent times the
  // prescribed velocity (the λ-rate of the force at moving nodes).
  void Add(const ShellState& state,
           Eigen::VectorXd& internal,
           std::vector<Eigen::Matrix3d>* blocks,
           const Eigen::VectorXd* velocity,
           Eigen::VectorXd* rate) const;

  // The energy whose gradient Add's forces are [J]: ½ k A (m/(kA) − g)² per
  // node pressed in (m the multiplier), ½ s |x − a|² per spring, and the
  // lagged friction potential μ λ_n f₀(|u|) per lagged contact.
  double Energy(const ShellState& state) const;

  // The stabilisation springs and the friction lags start again from
  // `state` (a converged step).
  void Commit(const ShellState& state);

  // Friction's lag moved to `state`: the normal forces and tangent planes it
  // has, the anchors of the last commit (a node that came into contact
  // since, anchored where the last converged step left it).
  // FrictionLagChange: the largest change of a node's normal force that
  // Relag would make, over the largest (0 without friction or contact).
  double FrictionLagChange(const ShellState& state) const;
  void Relag(const ShellState& state);
  // Friction starts from rest at `state` (after a jump): each node in
  // contact anchored where it is, with its normal force there.
  void RestartFriction(const ShellState& state);
  // Relag at a step's predicted state; true when nodes that had no friction
  // in the lag carry a tenth of the normal force there (the predictor, made
  // without their friction, slid them freely: it should be made again).
  bool LagAtPrediction(const ShellState& predicted);

  // What a pass of the solver may undo: multipliers and friction lags.
  struct Memory {
    std::vector<double> multipliers;
    std::vector<FrictionLag> lags;
  };
  Memory memory() const { return {multiplier_, lag_}; }
  void Restore(Memory m) {
    multiplier_ = std::move(m.multipliers);
    lag_ = std::move(m.lags);
  }
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
  // The names of the obstacles that some node touches, in scene order.
  std::vector<std::string> TouchedObstacles(const ShellState& state) const;
  // Nodes deeper than `depth` inside an obstacle, deepest first: "node N is
  // X mm inside 'table'" lines, for the start of a run.
  // `among`: only these nodes (empty: every node).
  std::vector<std::string> Penetrations(const ShellState& state,
                                        double depth,
                                        const std::vector<int>& among = {}) const;

  double penalty() const { return law_.penalty; }
  const NormalLaw& law() const { return law_; }
  double stabilization() const { return stabilization_; }
  double half_thickness() const { return half_thickness_; }
  double friction() const { return friction_; }
  double friction_slip() const { return friction_slip_; }
  const std::vector<double>& nodal_area() const { return area_; }

 private:
  // Calls f(node, obstacle, g, query) for every node in contact.
  template <typename F>
  void ForEachContact(const ShellState& state, F&& f) const;

  // The normal force obstacle `o` exerts on node `i`, its magnitude, the
  // tangent −∂force/∂x, k = −∂f_n/∂g and the energy.
  struct NodeResponse {
    Eigen::Vector3d force;
    double normal_force = 0;
    Eigen::Matrix3d stiffness;
    double normal_stiffness = 0;
    double energy = 0;
  };
  // Whether node i at gap g from obstacle o is in contact: inside the
  // barrier's band; or touching, or pushed by its multiplier (penalty).
  bool InContact(int i, int o, double g) const;
  static ObstaclePlacement PlacementOf(const ShellState& state, int o);
  // Obstacle o's distance at world x, with it where `state` has placed it.
  DistanceQuery Query(const ShellState& state, int o, const Eigen::Vector3d& x) const;
  // Calls f(node, obstacle, response) for every node with a friction lag.
  template <typename F>
  void ForEachFriction(const ShellState& state, F&& f) const;
  // The lag of contact `at` (node · obstacles + obstacle) at `state`, its
  // anchor from `from`; `carry`: the elastic slip from that anchor carries
  // over (a commit) instead of the anchor itself.
  FrictionLag LagAt(const ShellState& state, size_t at, const FrictionLag& from, bool carry) const;
  std::vector<FrictionLag> LagsAt(const ShellState& state) const;
  NodeResponse Respond(int i, int o, double g, const DistanceQuery& q) const;

  std::vector<NamedObstacle> obstacles_;
  std::vector<double> area_;  // tributary reference area per node [m²]
  NormalLaw law_;
  double stabilization_;
  std::vector<bool> held_;  // nodes without a spring
  double half_thickness_;
  double friction_;
  double friction_slip_;     // ε [m]
  Eigen::MatrixXd anchors_;  // node positions of the last converged step
  // Friction lags per node and obstacle (index i·obstacles + o); a zero
  // normal force where the node has none.
  std::vector<FrictionLag> lag_;
  std::vector<FrictionLag> committed_;  // lag_ at the last commit
  // Augmented-Lagrangian normal force per node and obstacle [N] (same index).
  std::vector<double> multiplier_;
};

// The fabric's flat (reference) area, over the Gauss points [m²].
double ReferenceArea(const ShellModel& model);

// ε for `contact.friction_slip` left out: 1e-3 of the mean element size, so
// a sticking node creeps far less than the mesh resolves [m].
double DefaultFrictionSlip(const ShellModel& model);

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
