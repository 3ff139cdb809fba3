#include "core/contact/contact_setup.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/model/obstacle_geometry.h"
#include "core/model/scene_error.h"
#include "core/model/string_format.h"

namespace drape {

bool HoldsRestrainRigidMotion(const ShellModel& model, const DofMap& dofs) {
  std::vector<Eigen::Vector3d> held;
  bool clamped = false;
  for (int i = 0; i < model.NodeCount(); ++i)
    if (dofs.IsFixed(kDofsPerNode * i)) {
      held.push_back(model.reference.positions.row(i).transpose());
      clamped = clamped || dofs.IsFixed(kDofsPerNode * i + 3);
    }
  if (held.size() < 2) return false;
  if (clamped) return true;
  const double tiny = 1e-12 * model.characteristic_length * model.characteristic_length;
  for (size_t a = 1; a < held.size(); ++a)
    for (size_t b = a + 1; b < held.size(); ++b)
      if ((held[a] - held[0]).cross(held[b] - held[0]).norm() > tiny) return true;
  return false;
}

std::unique_ptr<NodeContact> MakeNodeContact(const Scene& scene, const ShellModel& model) {
  if (scene.obstacles.empty()) return nullptr;
  std::vector<NamedObstacle> obstacles;
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    obstacles.push_back(
        {scene.obstacles[i].name,
         MakeObstacleGeometry(scene.obstacles[i], ".", "obstacles[" + std::to_string(i) + "]")});
  const double friction = scene.contact ? scene.contact->friction : 0.0;
  CheckFrictionSlip(scene, model.characteristic_length);
  CheckBarrierDistance(scene, model.characteristic_length);
  const double slip =
      scene.contact && scene.contact->friction_slip ? *scene.contact->friction_slip : 0.0;
  auto contact = std::make_unique<NodeContact>(
      model, std::move(obstacles), NormalLawFor(scene, model), 0.0, friction, slip);
  // A fabric that starts inside an obstacle has no meaningful first step.
  const auto inside = contact->Penetrations(model.reference, 1e-3 * model.thickness);
  if (!inside.empty()) {
    std::string message = "the fabric starts inside an obstacle: " + inside.front();
    if (inside.size() > 1) message += " (and " + std::to_string(inside.size() - 1) + " more nodes)";
    throw SceneError("obstacles", message + "; raise the fabric or move the obstacle");
  }
  // The barrier is infinite where the fabric's surface touches.
  if (contact->HasBarrier()) {
    const ClosestNode closest = contact->Closest(model.reference);
    if (closest.gap <= 1e-9 * model.thickness) {
      const auto x = model.reference.positions.row(closest.node);
      throw SceneError(
          "obstacles",
          Format("the fabric starts touching obstacle '%s': node %d at (%.4g, %.4g, %.4g) m is "
                 "%.4g mm from it, and the barrier contact (contact.law \"barrier\") needs a "
                 "gap; raise the fabric by a fraction of the barrier distance (%.4g mm), or use "
                 "contact.law \"penalty\"",
                 scene.obstacles[closest.obstacle].name.c_str(),
                 closest.node,
                 x(0),
                 x(1),
                 x(2),
                 1e3 * (closest.gap + 0.5 * model.thickness),
                 1e3 * contact->law().barrier_distance));
    }
  }
  return contact;
}

NormalLaw NormalLawFor(const Scene& scene, const ShellModel& model) {
  NormalLaw law;
  if (!scene.contact || scene.contact->law == ContactLaw::kPenalty) {
    law.penalty =
        scene.contact && scene.contact->penalty ? *scene.contact->penalty : AutoPenalty(model);
    return law;
  }
  law.barrier_distance =
      scene.contact->barrier_distance ? *scene.contact->barrier_distance : 0.5 * model.thickness;
  // Halfway into its band the barrier carries ten times the fabric's weight
  // per area w (−b'(d̂/2) = (½ + ln 2) d̂), as the self-contact's does a node's:
  // resting under its weight a node sits near the band's outer edge, and
  // pressed harder, closer in. Without weight, a millionth of the penalty.
  const double weight_per_area = model.total_weight.norm() / std::max(ReferenceArea(model), 1e-300);
  law.barrier_stiffness =
      std::max(10 * weight_per_area / ((0.5 + std::log(2.0)) * law.barrier_distance),
               1e-6 * AutoPenalty(model));
  return law;
}

namespace {

// A length of contact (`key`, described as `what`) that must be smaller
// than the part.
void CheckSmallerThanPart(const std::optional<double>& length,
                          const char* key,
                          const char* what,
                          double part_diagonal) {
  if (length && *length >= part_diagonal)
    throw SceneError(key,
                     Format("%s (%.4g mm) must be smaller than the part (its diagonal is %.4g mm)",
                            what,
                            1e3 * *length,
                            1e3 * part_diagonal));
}

}  // namespace

void CheckFrictionSlip(const Scene& scene, double part_diagonal) {
  if (scene.contact)
    CheckSmallerThanPart(scene.contact->friction_slip,
                         "contact.friction_slip",
                         "the slip at which friction slides",
                         part_diagonal);
}

void CheckBarrierDistance(const Scene& scene, double part_diagonal) {
  if (scene.contact)
    CheckSmallerThanPart(scene.contact->barrier_distance,
                         "contact.barrier_distance",
                         "the distance at which the barrier acts",
                         part_diagonal);
}

double LayerExclusion(const ShellModel& model, double element_size) {
  return std::max(4 * element_size, 10 * model.thickness);
}

SelfContactSettings SelfContactSettingsFor(const Scene& scene,
                                           const ShellModel& model,
                                           double exclusion) {
  SelfContactSettings s;
  s.offset =
      scene.contact && scene.contact->thickness ? *scene.contact->thickness : model.thickness;
  s.activation = 0.5 * s.offset;
  s.exclusion = exclusion;
  // Stiffness: the barrier halfway into its band carries ten times a node's
  // weight (its force there is κ·1.19ŝ·2(ξ + d̂/2), b'(ŝ/2) = −1.19ŝ); closer,
  // the log barrier grows without bound.
  const double s_hat = 2 * s.offset * s.activation + s.activation * s.activation;
  const double node_weight = model.total_weight.norm() / std::max(1, model.NodeCount());
  s.stiffness =
      10 * std::max(node_weight, 1e-12) / (2.39 * s_hat * (s.offset + 0.5 * s.activation));
  return s;
}

}  // namespace drape
