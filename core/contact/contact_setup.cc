#include "core/contact/contact_setup.h"

#include <algorithm>
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
  const double penalty =
      scene.contact && scene.contact->penalty ? *scene.contact->penalty : AutoPenalty(model);
  const double friction = scene.contact ? scene.contact->friction : 0.0;
  CheckFrictionSlip(scene, model.characteristic_length);
  const double slip =
      scene.contact && scene.contact->friction_slip ? *scene.contact->friction_slip : 0.0;
  auto contact =
      std::make_unique<NodeContact>(model, std::move(obstacles), penalty, 0.0, friction, slip);
  // A fabric that starts inside an obstacle has no meaningful first step.
  const auto inside = contact->Penetrations(model.reference, 1e-3 * model.thickness);
  if (!inside.empty()) {
    std::string message = "the fabric starts inside an obstacle: " + inside.front();
    if (inside.size() > 1) message += " (and " + std::to_string(inside.size() - 1) + " more nodes)";
    throw SceneError("obstacles", message + "; raise the fabric or move the obstacle");
  }
  return contact;
}

void CheckFrictionSlip(const Scene& scene, double part_diagonal) {
  if (!scene.contact || !scene.contact->friction_slip) return;
  const double slip = *scene.contact->friction_slip;
  if (slip >= part_diagonal)
    throw SceneError("contact.friction_slip",
                     Format("the slip at which friction slides (%.4g mm) must be smaller than the "
                            "part (its diagonal is %.4g mm)",
                            1e3 * slip,
                            1e3 * part_diagonal));
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
