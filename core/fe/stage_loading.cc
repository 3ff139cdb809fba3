#include "core/fe/stage_loading.h"

#include "core/fe/edge_moments.h"

namespace drape {

StageLoading::StageLoading(const ShellModel& model,
                           const Stage& stage,
                           const std::vector<HeldGripper>& grippers,
                           double weight_before,
                           double loads_before,
                           std::vector<MovedObstacle> obstacles)
    : model_(model),
      kind_(stage.kind),
      grippers_(grippers),
      obstacles_(std::move(obstacles)),
      weight_before_(weight_before),
      loads_before_(loads_before) {
  for (const auto& g : grippers_)
    if (g.path) moving_ = true;
}

double StageLoading::WeightFactor(double lambda) const {
  return kind_ == StageKind::kGravity ? lambda : weight_before_;
}

double StageLoading::LoadFactor(double lambda) const {
  return kind_ == StageKind::kLoad ? lambda : loads_before_;
}

std::vector<ObstacleMotion> StageLoading::ObstacleMotions(double lambda) const {
  std::vector<ObstacleMotion> motions;
  for (const auto& o : obstacles_) motions.push_back({o.index, MotionAt(*o.path, lambda)});
  return motions;
}

void StageLoading::Place(double lambda, ShellState& state) const {
  state.load_factor = LoadFactor(lambda);
  for (const auto& o : obstacles_) {
    // world = M(start(x)): R = R_M R₀, t = R_M (t₀ − c) + c + d.
    const RigidMotion m = MotionAt(*o.path, lambda);
    ObstaclePlacement& p = state.obstacles.at(o.index);
    p.rotation = m.rotation * o.start.rotation;
    p.translation = m.Apply(o.start.translation);
  }
  for (const auto& g : grippers_) {
    if (!g.path) continue;
    const RigidMotion motion = MotionAt(*g.path, lambda);
    for (size_t k = 0; k < g.gripper->nodes.size(); ++k) {
      const int node = g.gripper->nodes[k];
      state.positions.row(node) = motion.Apply(g.start_positions[k]).transpose();
      if (g.gripper->fixity == Fixity::kClamp)
        state.rotations[node] = motion.rotation * g.start_rotations[k];
    }
  }
}

Eigen::VectorXd StageLoading::PointLoads(const ShellState& s) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_.DofCount());
  for (const auto& load : model_.loads)
    for (int node : load.nodes) {
      f.segment<3>(kDofsPerNode * node) += load.force_per_node;
      // A moment M does work M·w on the rotation w = a g₁ + b g₂.
      const Eigen::Matrix3d& r = s.rotations[node];
      f(kDofsPerNode * node + 3) += load.moment_per_node.dot(r.col(0));
      f(kDofsPerNode * node + 4) += load.moment_per_node.dot(r.col(1));
    }
  return f;
}

Eigen::VectorXd StageLoading::External(double lambda, const ShellState& state) const {
  Eigen::VectorXd f = WeightFactor(lambda) * model_.weight_load;
  if (const double l = LoadFactor(lambda); l != 0) f += l * PointLoads(state);
  return f;
}

Eigen::VectorXd StageLoading::ExternalRate(const ShellState& state) const {
  if (kind_ == StageKind::kGravity) return model_.weight_load;
  if (kind_ == StageKind::kLoad) return PointLoads(state) + EdgeMomentForce(model_, state);
  return Eigen::VectorXd::Zero(model_.DofCount());
}

Eigen::VectorXd StageLoading::Velocity(double lambda, const ShellState& state) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model_.DofCount());
  for (const auto& g : grippers_) {
    if (!g.path) continue;
    const RigidMotion motion = MotionAt(*g.path, lambda);
    for (size_t k = 0; k < g.gripper->nodes.size(); ++k) {
      const int node = g.gripper->nodes[k];
      v.segment<3>(kDofsPerNode * node) = motion.Velocity(g.start_positions[k]);
      if (g.gripper->fixity == Fixity::kClamp) {
        const Eigen::Matrix3d& r = state.rotations[node];
        v(kDofsPerNode * node + 3) = motion.angular_rate.dot(r.col(0));
        v(kDofsPerNode * node + 4) = motion.angular_rate.dot(r.col(1));
      }
    }
  }
  return v;
}

double StageLoading::PrescribedSpeed(double lambda, const ShellState& state) const {
  const Eigen::VectorXd v = Velocity(lambda, state);
  double sum = 0;
  for (int i = 0; i < model_.NodeCount(); ++i) sum += v.segment<3>(kDofsPerNode * i).squaredNorm();
  return std::sqrt(sum);
}

}  // namespace drape
