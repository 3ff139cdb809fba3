// A result's grippers as a robot cell wants them (`drape export RESULT
// --format trajectory`, docs/plan.md): per converged step, each gripper's
// pose — the rigid motion its path prescribes, composed over the stages —
// the time at which a gripper moving at a stated speed gets there, and the
// force it carries.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <filesystem>
#include <string>
#include <vector>

#include "core/io/result_reader.h"

namespace drape {

struct GripperPose {
  bool held = true;                                                 // false from its release on
  Eigen::Vector3d position = Eigen::Vector3d::Zero();               // its held nodes' centroid [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // from the reference
  Eigen::Vector3d force = Eigen::Vector3d::Zero();                  // on the fabric [N]
};

struct TrajectoryPoint {
  int stage = 0, step = 0;
  std::string stage_name;
  double lambda = 0;
  double time_s = 0;
  std::vector<GripperPose> grippers;  // in the scene's order
};

// One point per stored state. `speed` [m/s] > 0: the fastest gripper of a
// stage moves along its path at it (stages that move no gripper take no
// time). Throws std::invalid_argument for a speed ≤ 0.
std::vector<TrajectoryPoint> GripperTrajectory(const RunRecord& record, double speed);

// CSV: step, stage, stage_name, lambda, time_s, then per gripper G:
// G_held, G_x_m, G_y_m, G_z_m, G_qw, G_qx, G_qy, G_qz, G_fx_N, G_fy_N,
// G_fz_N. Throws std::runtime_error when it cannot write.
void WriteTrajectoryCsv(const RunRecord& record,
                        const std::vector<TrajectoryPoint>& points,
                        const std::filesystem::path& file);

}  // namespace drape
