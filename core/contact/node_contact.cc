#include "core/contact/node_contact.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/contact/contact_barrier.h"

namespace drape {
namespace {

constexpr double kTouching = 1e-9;  // of the half thickness
// A node whose friction is this share of its Coulomb limit is sliding.
constexpr double kSliding = 0.999;
// A predicted state where nodes that had no friction carry this share of the
// normal force asks for the predictor again, with their friction.
constexpr double kFreshShare = 0.1;
// A step may close at most this share of a node's gap to an obstacle
// (barrier law), as the self-contact's collision filter does.
constexpr double kClose = 0.9;

double MeanElementSize(const ShellModel& model) {
  return std::sqrt(ReferenceArea(model) / std::max(1, model.mesh.ElementCount()));
}

}  // namespace

NodeContact::NodeContact(const ShellModel& model,
                         std::vector<NamedObstacle> obstacles,
                         const NormalLaw& law,
                         double stabilization,
                         double friction,
                         double friction_slip)
    : obstacles_(std::move(obstacles)),
      area_(model.NodeCount(), 0.0),
      law_(law),
      stabilization_(stabilization),
      half_thickness_(0.5 * model.thickness),
      friction_(friction),
      friction_slip_(friction_slip > 0 ? friction_slip : DefaultFrictionSlip(model)),
      anchors_(model.reference.positions),
      lag_(static_cast<size_t>(model.NodeCount()) * obstacles_.size()),
      committed_(lag_),
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
      if (InContact(i, static_cast<int>(o), g)) f(i, static_cast<int>(o), g, q, x);
    }
  }
}

bool NodeContact::InContact(int i, int o, double g) const {
  if (HasBarrier()) return g < law_.barrier_distance;
  // Touching counts (with no force): its stiffness lets a predictor see the
  // obstacle the fabric rests on. "Touching" allows for round-off in the
  // distance of a node placed exactly on a curved surface. A node with a
  // multiplier is in contact while it still pushes.
  const double m = multiplier_[static_cast<size_t>(i) * obstacles_.size() + o];
  return g <= kTouching * half_thickness_ || m - law_.penalty * area_[i] * g > 0.0;
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

template <typename F>
void NodeContact::ForEachFriction(const ShellState& state, F&& f) const {
  if (friction_ <= 0.0) return;
  const size_t count = obstacles_.size();
  for (size_t at = 0; at < lag_.size(); ++at) {
    const FrictionLag& lag = lag_[at];
    if (lag.normal_force <= 0.0) continue;
    const int i = static_cast<int>(at / count), o = static_cast<int>(at % count);
    const ObstaclePlacement p = PlacementOf(state, o);
    f(i,
      o,
      EvaluateFriction(state.positions.row(i).transpose(),
                       p.ToWorld(lag.anchor),
                       p.rotation * lag.basis,
                       friction_ * lag.normal_force,
                       friction_slip_));
  }
}

FrictionLag NodeContact::LagAt(const ShellState& state,
                               size_t at,
                               const FrictionLag& from,
                               bool carry) const {
  const int i = static_cast<int>(at / obstacles_.size());
  const int o = static_cast<int>(at % obstacles_.size());
  const ObstaclePlacement p = PlacementOf(state, o);
  const Eigen::Vector3d x = state.positions.row(i).transpose();
  const DistanceQuery q = Query(state, o, x);
  const double g = q.distance - half_thickness_;
  FrictionLag lag;
  if (!InContact(i, o, g)) return lag;
  lag.normal_force = Respond(i, o, g, q).normal_force;
  if (lag.normal_force <= 0.0) return lag;
  const Eigen::Matrix<double, 3, 2> basis = TangentBasis(q.normal);
  lag.basis = p.rotation.transpose() * basis;
  if (from.normal_force <= 0.0) {
    // A node that came into contact in this step sticks from where the last
    // converged step left it; at a commit, from where it is now.
    lag.anchor = p.ToScene(carry ? x : Eigen::Vector3d(anchors_.row(i).transpose()));
  } else if (!carry) {
    lag.anchor = from.anchor;
  } else {
    // The elastic part of the slip (at most ε) carries over, in the new
    // tangent plane: a node that slid drags its anchor along.
    const Eigen::Vector3d slip = basis * (basis.transpose() * (x - p.ToWorld(from.anchor)));
    const double length = slip.norm();
    lag.anchor = p.ToScene(
        length > friction_slip_ ? Eigen::Vector3d(x - slip * (friction_slip_ / length)) : x - slip);
  }
  return lag;
}

std::vector<FrictionLag> NodeContact::LagsAt(const ShellState& state) const {
  std::vector<FrictionLag> lags(lag_.size());
  for (size_t at = 0; at < lag_.size(); ++at) lags[at] = LagAt(state, at, committed_[at], false);
  return lags;
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
          const NodeResponse r = Respond(i, o, g, q);
          rate.segment<3>(kDofsPerNode * i) -=
              r.normal_stiffness * q.normal.dot(v) * q.normal + r.normal_force * n_rate;
        });
}

NodeContact::NodeResponse NodeContact::Respond(int i,
                                               int o,
                                               double g,
                                               const DistanceQuery& q) const {
  NodeResponse r;
  if (HasBarrier()) {
    // f_n = −κ A b'(g), k = κ A b''(g): both grow without bound as g → 0.
    const double kappa = law_.barrier_stiffness * area_[i];
    const BarrierValue b = ClampedLogBarrier(g, law_.barrier_distance);
    r.normal_force = -kappa * b.first;
    r.normal_stiffness = kappa * b.second;
    r.energy = kappa * b.value;
  } else {
    // f_n = m − k A g (m: the augmented-Lagrangian multiplier).
    const double k = law_.penalty * area_[i];
    r.normal_force =
        std::max(0.0, multiplier_[static_cast<size_t>(i) * obstacles_.size() + o] - k * g);
    r.normal_stiffness = k;
    r.energy = k > 0 ? 0.5 * r.normal_force * r.normal_force / k : 0.0;
  }
  // −∂(f_n n)/∂x = k n nᵀ − f_n ∇∇d.
  r.force = r.normal_force * q.normal;
  r.stiffness = r.normal_stiffness * q.normal * q.normal.transpose() - r.normal_force * q.hessian;
  return r;
}

void NodeContact::Add(const ShellState& state,
                      Eigen::VectorXd& internal,
                      std::vector<Eigen::Matrix3d>* blocks,
                      const Eigen::VectorXd* velocity,
                      Eigen::VectorXd* rate) const {
  const int n = state.NodeCount();
  if (blocks) blocks->assign(n, Eigen::Matrix3d::Zero());
  auto add = [&](int i, const Eigen::Vector3d& force, const Eigen::Matrix3d& stiffness) {
    internal.segment<3>(kDofsPerNode * i) -= force;
    if (blocks) (*blocks)[i] += stiffness;
    if (velocity && rate)
      rate->segment<3>(kDofsPerNode * i) += stiffness * velocity->segment<3>(kDofsPerNode * i);
  };
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d&) {
                   const NodeResponse r = Respond(i, o, g, q);
                   add(i, r.force, r.stiffness);
                 });
  ForEachFriction(state,
                  [&](int i, int, const FrictionResponse& f) { add(i, f.force, f.stiffness); });
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
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d&) {
                   energy += Respond(i, o, g, q).energy;
                 });
  ForEachFriction(state, [&](int, int, const FrictionResponse& f) { energy += f.energy; });
  if (stabilization_ <= 0.0) return energy;
  for (int i = 0; i < state.NodeCount(); ++i)
    if (held_.empty() || !held_[i])
      energy += 0.5 * stabilization_ * (state.positions.row(i) - anchors_.row(i)).squaredNorm();
  return energy;
}

void NodeContact::Augment(const ShellState& state) {
  if (HasBarrier()) return;  // no multipliers: no node is inside
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d&) {
                   multiplier_[static_cast<size_t>(i) * obstacles_.size() + o] =
                       Respond(i, o, g, q).normal_force;
                 });
}

double NodeContact::FrictionLagChange(const ShellState& state) const {
  if (friction_ <= 0.0) return 0.0;
  const std::vector<FrictionLag> now = LagsAt(state);
  double change = 0, largest = 0;
  for (size_t at = 0; at < lag_.size(); ++at) {
    change = std::max(change, std::abs(now[at].normal_force - lag_[at].normal_force));
    largest = std::max({largest, now[at].normal_force, lag_[at].normal_force});
  }
  return largest > 0 ? change / largest : 0.0;
}

void NodeContact::Relag(const ShellState& state) {
  if (friction_ > 0.0) lag_ = LagsAt(state);
}

void NodeContact::RestartFriction(const ShellState& state) {
  if (friction_ <= 0.0) return;
  for (size_t at = 0; at < lag_.size(); ++at) lag_[at] = LagAt(state, at, FrictionLag{}, true);
  committed_ = lag_;
  anchors_ = state.positions;
}

bool NodeContact::LagAtPrediction(const ShellState& predicted) {
  if (friction_ <= 0.0) return false;
  std::vector<FrictionLag> now = LagsAt(predicted);
  double total = 0, fresh = 0;
  for (size_t at = 0; at < lag_.size(); ++at) {
    total += now[at].normal_force;
    if (lag_[at].normal_force <= 0.0) fresh += now[at].normal_force;
  }
  lag_ = std::move(now);
  return fresh > kFreshShare * total;
}

void NodeContact::Commit(const ShellState& state) {
  // Multipliers stay with the nodes that still push (no jump in force from
  // one step to the next); those that let go start again from zero.
  std::vector<double> kept(multiplier_.size(), 0.0);
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d&) {
                   const size_t at = static_cast<size_t>(i) * obstacles_.size() + o;
                   if (Respond(i, o, g, q).normal_force > 0.0) kept[at] = multiplier_[at];
                 });
  if (friction_ > 0.0) {
    std::vector<FrictionLag> next(lag_.size());
    for (size_t at = 0; at < lag_.size(); ++at)
      next[at] = LagAt(state, at, lag_[at].normal_force > 0.0 ? lag_[at] : committed_[at], true);
    lag_ = std::move(next);
    committed_ = lag_;
  }
  multiplier_ = std::move(kept);
  anchors_ = state.positions;
}

ContactReport NodeContact::Report(const ShellState& state) const {
  ContactReport r;
  std::vector<Eigen::Vector3d> force(state.NodeCount(), Eigen::Vector3d::Zero());
  std::vector<double> normal(state.NodeCount(), 0.0);
  std::vector<bool> touching(state.NodeCount(), false);
  ForEachContact(state,
                 [&](int i, int o, double g, const DistanceQuery& q, const Eigen::Vector3d&) {
                   touching[i] = true;
                   const NodeResponse response = Respond(i, o, g, q);
                   force[i] += response.force;
                   normal[i] += response.normal_force;
                   r.max_penetration = std::max(r.max_penetration, std::max(-g, 0.0));
                 });
  r.with_friction = friction_ > 0.0;
  r.friction.assign(state.NodeCount(), SlipState::kNone);
  ForEachFriction(state, [&](int i, int, const FrictionResponse& f) {
    force[i] += f.force;
    r.friction_force += f.force;
    const SlipState s = f.mobilised >= kSliding ? SlipState::kSliding : SlipState::kSticking;
    r.friction[i] = std::max(r.friction[i], s);
  });
  r.nodes = static_cast<int>(std::count(touching.begin(), touching.end(), true));
  r.sticking =
      static_cast<int>(std::count(r.friction.begin(), r.friction.end(), SlipState::kSticking));
  r.sliding =
      static_cast<int>(std::count(r.friction.begin(), r.friction.end(), SlipState::kSliding));
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

std::vector<std::string> NodeContact::TouchedObstacles(const ShellState& state) const {
  std::vector<bool> touched(obstacles_.size(), false);
  ForEachContact(state, [&](int, int o, double, const DistanceQuery&, const Eigen::Vector3d&) {
    touched[o] = true;
  });
  std::vector<std::string> names;
  for (size_t o = 0; o < obstacles_.size(); ++o)
    if (touched[o]) names.push_back(obstacles_[o].name);
  return names;
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

ClosestNode NodeContact::Closest(const ShellState& state) const {
  ClosestNode closest;
  for (int i = 0; i < state.NodeCount(); ++i)
    for (size_t o = 0; o < obstacles_.size(); ++o) {
      const double g =
          Query(state, static_cast<int>(o), state.positions.row(i).transpose()).distance -
          half_thickness_;
      if (g < closest.gap) closest = {g, i, static_cast<int>(o)};
    }
  return closest;
}

double NodeContact::StepBound(const ShellState& state, const Eigen::MatrixX3d& dx) const {
  if (!HasBarrier()) return 1.0;
  double bound = 1.0;
  for (int i = 0; i < state.NodeCount(); ++i) {
    const Eigen::Vector3d step = dx.row(i).transpose();
    const double length = step.norm();
    if (length == 0.0) continue;
    const Eigen::Vector3d x = state.positions.row(i).transpose();
    for (size_t o = 0; o < obstacles_.size(); ++o) {
      const DistanceQuery q = Query(state, static_cast<int>(o), x);
      const double g = q.distance - half_thickness_;
      // Already inside (never after a bounded step) or out of reach.
      if (g <= 0.0 || length * bound <= kClose * g) continue;
      // d(x + t dx) ≥ d(x) + t ∇d·dx outside a convex obstacle.
      const double closing = -q.normal.dot(step);
      double t = closing > 0.0 ? std::min(bound, kClose * g / closing) : bound;
      if (!obstacles_[o].geometry->IsConvex()) {
        auto gap_at = [&](double s) {
          return Query(state, static_cast<int>(o), x + s * step).distance - half_thickness_;
        };
        for (int halving = 0; halving < 60 && gap_at(t) < (1 - kClose) * g; ++halving) t *= 0.5;
      }
      bound = std::min(bound, t);
    }
  }
  return bound;
}

double ReferenceArea(const ShellModel& model) {
  double area = 0;
  for (const auto& element : model.elements)
    for (const auto& gp : element.gauss) area += gp.area;
  return area;
}

double DefaultFrictionSlip(const ShellModel& model) {
  return 1e-3 * MeanElementSize(model);
}

double AutoPenalty(const ShellModel& model) {
  const double size = MeanElementSize(model);
  const double element_area = size * size;
  // The membrane stiffness: the largest of D_m's diagonal (E h/(1 − ν²) for
  // an isotropic section).
  const double membrane = model.section.membrane.diagonal().maxCoeff();
  return membrane / element_area;
}

}  // namespace drape
