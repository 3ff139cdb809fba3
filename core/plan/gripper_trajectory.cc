#include "core/plan/gripper_trajectory.h"

#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/fe/prescribed_motion.h"
#include "core/model/node_selection.h"
#include "core/plan/held_nodes.h"

namespace drape {
namespace {

// Samples per stage to measure how far along its path a gripper is at λ.
constexpr int kLengthSamples = 400;

// A gripper's motion over the stages before the current one, composed:
// x = R x₀ + t.
struct Pose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d Apply(const Eigen::Vector3d& x) const { return rotation * x + translation; }
};

Pose Then(const Pose& before, const RigidMotion& m) {
  // m.Apply(x) = R (x − c) + c + d
  Pose p;
  p.rotation = m.rotation * before.rotation;
  p.translation = m.rotation * (before.translation - m.center) + m.center + m.translation;
  return p;
}

const Path* PathOf(const Stage& stage, const std::string& gripper) {
  for (const Move& m : stage.moves)
    if (m.gripper == gripper) return &m.path;
  return nullptr;
}

// The length of the path a point x₀ travels from λ = 0 to `lambda`.
double LengthTo(const Path& path, const Eigen::Vector3d& x0, double lambda) {
  double length = 0;
  Eigen::Vector3d last = MotionAt(path, 0).Apply(x0);
  const int n = std::max(1, static_cast<int>(std::ceil(kLengthSamples * lambda)));
  for (int k = 1; k <= n; ++k) {
    const Eigen::Vector3d at = MotionAt(path, lambda * k / n).Apply(x0);
    length += (at - last).norm();
    last = at;
  }
  return length;
}

}  // namespace

std::vector<TrajectoryPoint> GripperTrajectory(const RunRecord& record, double speed) {
  if (!(speed > 0)) throw std::invalid_argument("the gripper speed must be greater than zero");
  const Scene& scene = record.scene;
  const size_t count = scene.grippers.size();
  std::vector<Eigen::Vector3d> start(count);  // each gripper's centroid in the reference
  std::vector<int> releases(count);
  for (size_t g = 0; g < count; ++g) {
    start[g] = Centroid(record.mesh.positions,
                        SelectNodesInParts(scene.grippers[g].select, scene, record.mesh));
    releases[g] = ReleaseStage(scene, scene.grippers[g].name);
  }
  // Poses at the start of each stage, and the time each stage starts at.
  std::vector<std::vector<Pose>> at_stage(scene.stages.size() + 1, std::vector<Pose>(count));
  std::vector<double> stage_time(scene.stages.size() + 1, 0);
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    double longest = 0;
    for (size_t g = 0; g < count; ++g) {
      const Path* path = PathOf(scene.stages[s], scene.grippers[g].name);
      at_stage[s + 1][g] = path ? Then(at_stage[s][g], MotionAt(*path, 1)) : at_stage[s][g];
      if (path) longest = std::max(longest, LengthTo(*path, at_stage[s][g].Apply(start[g]), 1));
    }
    stage_time[s + 1] = stage_time[s] + longest / speed;
  }
  std::vector<TrajectoryPoint> points;
  for (size_t i = 0; i < record.states.size(); ++i) {
    const StoredStep& state = record.states[i];
    const size_t s = static_cast<size_t>(state.stage);
    if (s >= scene.stages.size()) continue;
    TrajectoryPoint p;
    p.stage = state.stage;
    p.step = state.step;
    p.stage_name = scene.stages[s].name;
    p.lambda = state.lambda;
    double longest = 0;
    for (size_t g = 0; g < count; ++g) {
      GripperPose pose;
      const Path* path = PathOf(scene.stages[s], scene.grippers[g].name);
      const Pose now = path ? Then(at_stage[s][g], MotionAt(*path, state.lambda)) : at_stage[s][g];
      if (path)
        longest = std::max(longest, LengthTo(*path, at_stage[s][g].Apply(start[g]), state.lambda));
      pose.held = state.stage < releases[g];
      pose.position = now.Apply(start[g]);
      pose.orientation = Eigen::Quaterniond(now.rotation).normalized();
      if (pose.orientation.w() < 0) pose.orientation.coeffs() *= -1;  // one of ±q: w ≥ 0
      if (i < record.steps.size())
        for (const NamedVector& r : record.steps[i].reactions)
          if (r.name == scene.grippers[g].name) pose.force = r.value;
      p.grippers.push_back(pose);
    }
    p.time_s = stage_time[s] + longest / speed;
    points.push_back(std::move(p));
  }
  return points;
}

void WriteTrajectoryCsv(const RunRecord& record,
                        const std::vector<TrajectoryPoint>& points,
                        const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
  out << "step,stage,stage_name,lambda,time_s";
  for (const Gripper& g : record.scene.grippers)
    for (const char* column :
         {"held", "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "fx_N", "fy_N", "fz_N"})
      out << "," << g.name << "_" << column;
  out << "\n";
  char number[40];
  auto put = [&](double v) {
    std::snprintf(number, sizeof number, ",%.12g", v);
    out << number;
  };
  for (const TrajectoryPoint& p : points) {
    out << p.step << "," << p.stage << "," << p.stage_name;
    put(p.lambda);
    put(p.time_s);
    for (const GripperPose& g : p.grippers) {
      out << "," << (g.held ? 1 : 0);
      for (int k = 0; k < 3; ++k) put(g.position[k]);
      put(g.orientation.w());
      put(g.orientation.x());
      put(g.orientation.y());
      put(g.orientation.z());
      for (int k = 0; k < 3; ++k) put(g.force[k]);
    }
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace drape
