#include "core/contact/node_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace drape {
namespace {

constexpr double kTouching = 1e-9;  // of the half thickness
// Slip kept from step to step, in units of the regularisation ε: 3ε gives
// 3/√10 = 95 % of μ f_n.
constexpr double kCarriedSlip = 3.0;

}  // namespace

NodeContact::NodeContact(const ShellModel& model,
                         std::vector<NamedObstacle> obstacles,
                         double penalty,
                         double stabilization,
                         double friction)
    : obstacles_(std::move(obstacles)),
      area_(model.NodeCount(), 0.0),
      penalty_(penalty),
      stabilization_(stabilization),
      half_thickness_(0.5 * model.thickness),
      friction_(friction),
      anchors_(model.reference.positions),
      stick_(static_cast<size_t>(model.NodeCount()) * obstacles_.size(),
             Eigen::Vector3d::Constant(std::nan(""))),
      multiplier_(static_cast<size_t>(model.NodeCount()) * obstacles_.size(), 0.0) {
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
      const DistanceQuery q = Query(state, static_cast<int>(o), x);
      const double g = q.distance - half_thickness_;
      // Touching counts (with no force): its stiffness lets a predictor see
      // the obstacle the fabric rests on. "Touching" allows for round-off in
      // the distance of a node placed exactly on a curved surface. A node
      // with a multiplier is in contact while it still pushes.
      const double m = multiplier_[static_cast<size_t>(i) * obstacles_.size() + o];
      if (g <= kTouching * half_thickness_ || m - penalty_ * area_[i] * g > 0.0)
        f(i, static_cast<int>(o), g, q, x);
    }
  }
}

ObstaclePlacement NodeContact::PlacementOf(const ShellState& state, int o) {
  return state.obstacles.empty() ? ObstaclePlacement{} : state.obstacles[o];
}

DistanceQuery NodeContact::Query(const ShellState& state, int o, const Eigen::Vector3d& x) const {
  const ObstaclePlacement p = PlacementOf(state, o);
  if (p.IsIdentity()) return obstacles_[o].geometry->Query(x);
  DistanceQuery q = obstacles_[o].geometry->Query(p.ToScene(x));
  q.normal = p.rotation * q.normal;
  q.hessian = p.rotation * q.hessian * p.rotation.transpose();
  return q;
}

Eigen::Vector3d NodeContact::FrictionAnchor(const ShellState& state, int i, int o) const {
  // A node that came into contact during this step sticks from where it was
  // at the last converged step. Anchors move with their obstacle.
  const Eigen::Vector3d& stuck = stick_[static_cast<size_t>(i) * obstacles_.size() + o];
  return stuck.hasNaN() ? Eigen::Vector3d(anchors_.row(i).transpose())
                        : PlacementOf(state, o).ToWorld(stuck);
}

void NodeContact::AddObstacleRate(const ShellState& state,
                                  const std::vector<ObstacleMotion>& motions,
                                  Eigen::VectorXd& rate) const {
  for (const auto& m : motions)
    ForEachContact(
        state, [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
          if (o != m.index) return;
          // The obstacle's material point at x moves with v = ω × (x − c − d) + ḋ;
          // then ġ = −n·v and ṅ = ω × n − ∇∇d v at the fixed node. (Friction's
          // rate is left out, as its dependence on f_n is in the tangent.)
          const Eigen::Vector3d v =
              m.motion.angular_rate.cross(x - m.motion.center - m.motion.translation) +
              m.motion.translation_rate;
          const Eigen::Vector3d n_rate = m.motion.angular_rate.cross(q.normal) - q.hessian * v;
          const double k = penalty_ * area_[i];
          const double f_n =
              std::max(0.0, multiplier_[static_cast<size_t>(i) * obstacles_.size() + o] - k * g);
          rate.segment<3>(kDofsPerNode * i) -= k * q.normal.dot(v) * q.normal + f_n * n_rate;
        });
}

NodeContact::NodeResponse NodeContact::Respond(const ShellState& state,
                                               int i,
                                               int o,
                                               double g,
                                               const DistanceQuery& q,
                                               const Eigen::Vector3d& x) const {
  const double k = penalty_ * area_[i];
  const Eigen::Vector3d& n = q.normal;
  NodeResponse r;
  // f_n = m − k A g (m: the augmented-Lagrangian multiplier), and
  // −∂(f_n n)/∂x = k A n nᵀ − f_n ∇∇d.
  r.normal_force =
      std::max(0.0, multiplier_[static_cast<size_t>(i) * obstacles_.size() + o] - k * g);
  r.force = r.normal_force * n;
  r.stiffness = k * n * n.transpose() - r.normal_force * q.hessian;
  if (friction_ <= 0.0 || r.normal_force <= 0.0) return r;
  const Eigen::Vector3d anchor = FrictionAnchor(state, i, o);
  const Eigen::Matrix3d tangential = Eigen::Matrix3d::Identity() - n * n.transpose();
  const Eigen::Vector3d slip = tangential * (x - anchor);
  // Smooth Coulomb law f_t = −μ f_n s / √(|s|² + ε²) with ε = μ f_n / (k A):
  // stiffness k A for small slip (stick), μ f_n for large (slide), and no
  // switch between the two for Newton to chatter on.
  const double limit = friction_ * r.normal_force;
  const double epsilon = limit / k;
  const double root = std::sqrt(slip.squaredNorm() + epsilon * epsilon);
  r.force -= limit / root * slip;
  // The dependence on f_n (unsymmetric, and indefinite in its symmetric
  // part) is left out; what stays is positive semidefinite.
  r.stiffness += limit / root * (tangential - slip * slip.transpose() / (root * root));
  return r;
}

void NodeContact::Add(const ShellState& state,
                      Eigen::VectorXd& internal,
                      std::vector<Eigen::Matrix3d>* blocks,
                      const Eigen::VectorXd* velocity,
                      Eigen::VectorXd* rate) const {
  const int n = state.NodeCount();
  if (blocks) blocks->assign(n, Eigen::Matrix3d::Zero());
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   const NodeResponse r = Respond(state, i, o, g, q, x);
                   internal.segment<3>(kDofsPerNode * i) -= r.force;
                   if (blocks) (*blocks)[i] += r.stiffness;
                   if (velocity && rate)
                     rate->segment<3>(kDofsPerNode * i) +=
                         r.stiffness * velocity->segment<3>(kDofsPerNode * i);
                 });
  if (stabilization_ <= 0.0) return;
  for (int i = 0; i < n; ++i) {
    if (!held_.empty() && held_[i]) continue;
    internal.segment<3>(kDofsPerNode * i) +=
        stabilization_ * (state.positions.row(i) - anchors_.row(i)).transpose();
    if (blocks) (*blocks)[i].diagonal().array() += stabilization_;
  }
}

double NodeContact::Energy(const ShellState& state) const {
  double energy = 0;
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   const double f_n = Respond(state, i, o, g, q, x).normal_force;
                   energy += 0.5 * f_n * f_n / (penalty_ * area_[i]);
                 });
  if (stabilization_ <= 0.0) return energy;
  for (int i = 0; i < state.NodeCount(); ++i)
    if (held_.empty() || !held_[i])
      energy += 0.5 * stabilization_ * (state.positions.row(i) - anchors_.row(i)).squaredNorm();
  return energy;
}

void NodeContact::Augment(const ShellState& state) {
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   multiplier_[static_cast<size_t>(i) * obstacles_.size() + o] =
                       Respond(state, i, o, g, q, x).normal_force;
                 });
}

void NodeContact::Commit(const ShellState& state) {
  anchors_ = state.positions;
  // Multipliers stay with the nodes that still push (no jump in force from
  // one step to the next); those that let go start again from zero.
  std::vector<double> kept(multiplier_.size(), 0.0);
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   const size_t at = static_cast<size_t>(i) * obstacles_.size() + o;
                   if (Respond(state, i, o, g, q, x).normal_force > 0.0) kept[at] = multiplier_[at];
                 });
  multiplier_ = std::move(kept);
  if (friction_ <= 0.0) return;
  std::vector<Eigen::Vector3d> next(stick_.size(), Eigen::Vector3d::Constant(std::nan("")));
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   const size_t at = static_cast<size_t>(i) * obstacles_.size() + o;
                   // The slip carries over, so a node whose friction balances its load
                   // stays put in the next step; but only its elastic part, at most
                   // kCarriedSlip ε (95 % of the Coulomb force): a node that slid
                   // drags its anchor along, and its friction turns round once it
                   // moves back by about that much, as Coulomb friction does.
                   const Eigen::Vector3d anchor = FrictionAnchor(state, i, o);
                   const Eigen::Matrix3d tangential =
                       Eigen::Matrix3d::Identity() - q.normal * q.normal.transpose();
                   Eigen::Vector3d slip = tangential * (x - anchor);
                   const double f_n = Respond(state, i, o, g, q, x).normal_force;
                   const double carried = kCarriedSlip * friction_ * f_n / (penalty_ * area_[i]);
                   if (slip.norm() > carried) slip *= carried / slip.norm();
                   next[at] = PlacementOf(state, o).ToScene(x - slip);
                 });
  stick_ = std::move(next);
}

ContactReport NodeContact::Report(const ShellState& state) const {
  ContactReport r;
  std::vector<Eigen::Vector3d> force(state.NodeCount(), Eigen::Vector3d::Zero());
  std::vector<double> normal(state.NodeCount(), 0.0);
  std::vector<bool> touching(state.NodeCount(), false);
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d& x) {
                   touching[i] = true;
                   const NodeResponse response = Respond(state, i, o, g, q, x);
                   force[i] += response.force;
                   normal[i] += response.normal_force;
                   r.max_penetration = std::max(r.max_penetration, std::max(-g, 0.0));
                 });
  r.nodes = static_cast<int>(std::count(touching.begin(), touching.end(), true));
  r.pressure.assign(state.NodeCount(), 0.0);
  for (int i = 0; i < state.NodeCount(); ++i) {
    r.force += force[i];
    if (area_[i] > 0.0) r.pressure[i] = normal[i] / area_[i];
  }
  if (stabilization_ > 0.0)
    for (int i = 0; i < state.NodeCount(); ++i) {
      if (!held_.empty() && held_[i]) continue;
      const Eigen::Vector3d f =
          -stabilization_ * (state.positions.row(i) - anchors_.row(i)).transpose();
      r.stabilization_force += f;
      r.max_stabilization_force = std::max(r.max_stabilization_force, f.norm());
    }
  return r;
}

std::vector<std::string> NodeContact::Penetrations(const ShellState& state,
                                                   double depth,
                                                   const std::vector<int>& among) const {
  std::vector<std::pair<double, std::string>> found;
  ForEachContact(state, [&](int i, int o, double g, const DistanceQuery&, const Eigen::Vector3d&) {
    if (-g <= depth) return;
    if (!among.empty() && std::find(among.begin(), among.end(), i) == among.end()) return;
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
    found.emplace_back(-g, text);
  });
  std::stable_sort(
      found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::string> lines;
  for (auto& f : found) lines.push_back(std::move(f.second));
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
