// How one stage's loads and prescribed motions depend on its λ: the weight
// ramps in a gravity stage, point loads in a load stage, and grippers follow
// their paths in a move stage. Everything the steppers need to know about λ.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "core/fe/dof_map.h"
#include "core/fe/prescribed_motion.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/model/scene.h"

namespace drape {

// A gripper's nodes where the stage found them, and the path they follow in
// it (none: held in place).
struct HeldGripper {
  const HeldNodes* gripper = nullptr;
  const Path* path = nullptr;
  std::vector<Eigen::Vector3d> start_positions;
  std::vector<Eigen::Matrix3d> start_rotations;
};

// An obstacle a stage carries along a path, from where the stage found it.
struct MovedObstacle {
  int index = -1;  // in the scene's obstacles
  const Path* path = nullptr;
  ObstaclePlacement start;
};

// An obstacle's motion at λ: its placement and velocity field.
struct ObstacleMotion {
  int index = -1;
  RigidMotion motion;  // applied to the placement the stage started from
};

class StageLoading {
 public:
  // `weight_before` and `loads_before`: the factors reached by earlier stages.
  StageLoading(const ShellModel& model,
               const Stage& stage,
               const std::vector<HeldGripper>& grippers,
               double weight_before,
               double loads_before,
               std::vector<MovedObstacle> obstacles = {});

  // Puts the prescribed nodes where λ says (positions; rotations too for
  // clamps), and the moving obstacles.
  void Place(double lambda, ShellState& state) const;
  // The moving obstacles' motions at λ (their velocity fields make the
  // λ-rate of the contact force).
  std::vector<ObstacleMotion> ObstacleMotions(double lambda) const;
  // F_ext at λ, full (5 per node); moments act in the state's nodal bases.
  Eigen::VectorXd External(double lambda, const ShellState& state) const;
  // ∂F_ext/∂λ, full.
  Eigen::VectorXd ExternalRate(const ShellState& state) const;
  // ∂(prescribed DOFs)/∂λ at λ, full, zero on free DOFs; rotation rates in the
  // nodal bases (the drilling part has no DOF).
  Eigen::VectorXd Velocity(double lambda, const ShellState& state) const;
  // ‖∂u_p/∂λ‖ over the prescribed positions [m]: the grippers' speed in λ.
  double PrescribedSpeed(double lambda, const ShellState& state) const;

  bool MovesGrippers() const { return moving_; }
  bool MovesObstacles() const { return !obstacles_.empty(); }
  double WeightFactor(double lambda) const;
  double LoadFactor(double lambda) const;

 private:
  Eigen::VectorXd PointLoads(const ShellState& state) const;

  const ShellModel& model_;
  StageKind kind_;
  std::vector<HeldGripper> grippers_;
  std::vector<MovedObstacle> obstacles_;
  double weight_before_, loads_before_;
  bool moving_ = false;
};

}  // namespace drape
