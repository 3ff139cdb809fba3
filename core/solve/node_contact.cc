#include "core/solve/node_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace drape {

NodeContact::NodeContact(const ShellModel& model,
                         std::vector<NamedObstacle> obstacles,
                         double penalty,
                         double stabilization)
    : obstacles_(std::move(obstacles)),
      area_(model.NodeCount(), 0.0),
      penalty_(penalty),
      stabilization_(stabilization),
      half_thickness_(0.5 * model.thickness),
      anchors_(model.reference.positions) {
  // The consistent share ∫ N_I dA, as for the self-weight.
  for (int e = 0; e < model.mesh.ElementCount(); ++e)
    for (const auto& gp : model.elements[e].gauss)
      for (int k = 0; k < 4; ++k) area_[model.mesh.quads(e, k)] += gp.n(k) * gp.area;
}

template <typename F>
void NodeContact::ForEachContact(const ShellState& state, F&& f) const {
  for (int i = 0; i < state.NodeCount(); ++i) {
    const Eigen::Vector3d x = state.positions.row(i).transpose();
    for (size_t o = 0; o < obstacles_.size(); ++o) {
      const DistanceQuery q = obstacles_[o].geometry->Query(x);
      const double g = q.distance - half_thickness_;
      // Touching (g = 0) counts: its stiffness lets a predictor see the
      // obstacle it rests on.
      if (g <= 0.0) f(i, static_cast<int>(o), g, q);
    }
  }
}

void NodeContact::Add(const ShellState& state,
                      Eigen::VectorXd& internal,
                      std::vector<Eigen::Matrix3d>* blocks,
                      const Eigen::VectorXd* velocity,
                      Eigen::VectorXd* rate) const {
  const int n = state.NodeCount();
  if (blocks) blocks->assign(n, Eigen::Matrix3d::Zero());
  ForEachContact(state, [&](int i, int, double g, const DistanceQuery& q) {
    const double k = penalty_ * area_[i];
    internal.segment<3>(kDofsPerNode * i) += k * g * q.normal;
    if (!blocks && !(velocity && rate)) return;
    const Eigen::Matrix3d stiffness = k * (q.normal * q.normal.transpose() + g * q.hessian);
    if (blocks) (*blocks)[i] += stiffness;
    if (velocity && rate)
      rate->segment<3>(kDofsPerNode * i) += stiffness * velocity->segment<3>(kDofsPerNode * i);
  });
  if (stabilization_ <= 0.0) return;
  for (int i = 0; i < n; ++i) {
    internal.segment<3>(kDofsPerNode * i) +=
        stabilization_ * (state.positions.row(i) - anchors_.row(i)).transpose();
    if (blocks) (*blocks)[i].diagonal().array() += stabilization_;
  }
}

void NodeContact::Commit(const ShellState& state) {
  anchors_ = state.positions;
}

ContactReport NodeContact::Report(const ShellState& state) const {
  ContactReport r;
  std::vector<Eigen::Vector3d> force(state.NodeCount(), Eigen::Vector3d::Zero());
  std::vector<bool> touching(state.NodeCount(), false);
  ForEachContact(state, [&](int i, int, double g, const DistanceQuery& q) {
    touching[i] = true;
    force[i] -= penalty_ * area_[i] * g * q.normal;
    r.max_penetration = std::max(r.max_penetration, -g);
  });
  r.nodes = static_cast<int>(std::count(touching.begin(), touching.end(), true));
  r.pressure.assign(state.NodeCount(), 0.0);
  for (int i = 0; i < state.NodeCount(); ++i) {
    r.force += force[i];
    if (area_[i] > 0.0) r.pressure[i] = force[i].norm() / area_[i];
  }
  if (stabilization_ > 0.0)
    for (int i = 0; i < state.NodeCount(); ++i) {
      const Eigen::Vector3d f =
          -stabilization_ * (state.positions.row(i) - anchors_.row(i)).transpose();
      r.stabilization_force += f;
      r.max_stabilization_force = std::max(r.max_stabilization_force, f.norm());
    }
  return r;
}

std::vector<std::string> NodeContact::Penetrations(const ShellState& state, double depth) const {
  std::vector<std::string> lines;
  ForEachContact(state, [&](int i, int o, double g, const DistanceQuery&) {
    if (-g <= depth) return;
    char text[200];
    const auto x = state.positions.row(i);
    std::snprintf(text,
                  sizeof text,
                  "node %d at (%.4g, %.4g, %.4g) m is %.4g mm inside obstacle '%s'",
                  i,
                  x(0),
                  x(1),
                  x(2),
                  -g * 1e3,
                  obstacles_[o].name.c_str());
    lines.push_back(text);
  });
  return lines;
}

double AutoPenalty(const ShellModel& model) {
  double area = 0;
  for (const auto& element : model.elements)
    for (const auto& gp : element.gauss) area += gp.area;
  const double element_area = area / std::max(1, model.mesh.ElementCount());
  // The membrane stiffness: the largest of D_m's diagonal (E h/(1 − ν²) for
  // an isotropic section).
  const double membrane = model.section.membrane.diagonal().maxCoeff();
  return membrane / element_area;
}

}  // namespace drape
