#include "core/fe/shell_model.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "core/fe/edge_moments.h"
#include "core/fe/element_state.h"
#include "core/fe/material_section.h"
#include "core/mechanics/bilinear_quad.h"
#include "core/mechanics/director.h"
#include "core/model/fabric_mesh.h"
#include "core/model/node_selection.h"
#include "core/model/outline_geometry.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/model/vec3_eigen.h"

namespace drape {
namespace {

// Nodal directors of the reference surface: the normalised sum of the normals
// of the quads around each node (e₃ exactly on a flat sheet).
Eigen::Matrix<double, Eigen::Dynamic, 3> ReferenceDirectors(const Mesh& mesh) {
  Eigen::Matrix<double, Eigen::Dynamic, 3> t =
      Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(mesh.NodeCount(), 3);
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d p = mesh.positions.row(mesh.quads(e, k));
      const Eigen::Vector3d next = mesh.positions.row(mesh.quads(e, (k + 1) % 4));
      const Eigen::Vector3d prev = mesh.positions.row(mesh.quads(e, (k + 3) % 4));
      t.row(mesh.quads(e, k)) += (next - p).cross(prev - p).transpose();
    }
  }
  for (int i = 0; i < mesh.NodeCount(); ++i) t.row(i).normalize();
  return t;
}

}  // namespace

bool LocateInElement(const Mesh& mesh, int e, const Vec2& p, double& xi, double& eta) {
  Eigen::Matrix<double, 2, 4> corners;
  for (int k = 0; k < 4; ++k) corners.col(k) = mesh.positions.row(mesh.quads(e, k)).head<2>();
  xi = eta = 0;
  const Eigen::Vector2d target(p[0], p[1]);
  const double size =
      (corners.col(2) - corners.col(0)).norm() + (corners.col(3) - corners.col(1)).norm();
  for (int it = 0; it < 20; ++it) {
    Eigen::Vector4d n;
    Eigen::Matrix<double, 4, 2> dn;
    BilinearShape(xi, eta, n, &dn);
    const Eigen::Vector2d x = corners * n;
    const Eigen::Matrix2d j = corners * dn;
    const Eigen::Vector2d step = j.inverse() * (target - x);
    xi += step(0);
    eta += step(1);
    if (step.norm() < 1e-13) break;
  }
  // Newton from a point far outside the element may stop anywhere, inside
  // the square too: only a (ξ, η) that maps onto p locates it.
  Eigen::Vector4d n;
  BilinearShape(xi, eta, n, nullptr);
  if (!((corners * n - target).norm() <= 1e-9 * size)) return false;
  const double slack = 1e-9;
  return std::abs(xi) <= 1 + slack && std::abs(eta) <= 1 + slack;
}

ShellModel BuildShellModel(const Scene& scene) {
  return BuildShellModel(scene, MeshFabricParts(SceneOnSolvedMesh(scene)));
}

ShellModel BuildShellModel(const Scene& scene, Mesh reference_mesh) {
  ShellModel model;
  model.mesh = std::move(reference_mesh);
  const Mesh& mesh = model.mesh;
  MaterialSection material = MakeMaterialSection(scene.material);
  model.section = std::move(material.section);
  model.bending_valid_to = material.bending_valid_to;
  model.warnings = std::move(material.warnings);
  model.characteristic_length = PartsSize(scene);
  model.thickness = scene.material.thickness;

  const double angle = scene.material.angle_deg * M_PI / 180.0;
  const Eigen::Vector3d material_x(std::cos(angle), std::sin(angle), 0.0);
  const auto directors = ReferenceDirectors(mesh);
  model.reference.positions = mesh.positions;
  model.reference.rotations.resize(mesh.NodeCount());
  for (int i = 0; i < mesh.NodeCount(); ++i)
    model.reference.rotations[i] = RotationFromDirector(directors.row(i).transpose());

  const Eigen::Vector3d gravity = ToEigen(scene.gravity_direction);
  model.weight_load = Eigen::VectorXd::Zero(model.DofCount());
  model.elements.reserve(mesh.ElementCount());
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    NodeColumns x, t;
    for (int k = 0; k < 4; ++k) {
      x.col(k) = mesh.positions.row(mesh.quads(e, k)).transpose();
      t.col(k) = directors.row(mesh.quads(e, k)).transpose();
    }
    model.elements.push_back(MakeShellElementReference(x, t, material_x));
    // Consistent self-weight: F_I = w g ∫ N_I dA over the reference surface.
    for (const auto& gp : model.elements.back().gauss)
      for (int k = 0; k < 4; ++k)
        model.weight_load.segment<3>(kDofsPerNode * mesh.quads(e, k)) +=
            scene.material.areal_weight * gp.n(k) * gp.area * gravity;
  }
  for (int i = 0; i < mesh.NodeCount(); ++i)
    model.total_weight += model.weight_load.segment<3>(kDofsPerNode * i);

  const auto selections = ResolveSelections(scene, mesh);
  size_t s = 0;
  for (const auto& support : scene.supports)
    model.supports.push_back({support.name, selections[s++].nodes, support.fix});
  for (const auto& gripper : scene.grippers)
    model.grippers.push_back({gripper.name, selections[s++].nodes, gripper.hold});
  for (const auto& load : scene.loads) {
    model.loads.push_back(MakeNodalLoad(mesh,
                                        model.reference,
                                        load.name,
                                        selections[s++].nodes,
                                        ToEigen(load.force),
                                        ToEigen(load.moment)));
  }
  for (const auto& probe : scene.probes)
    model.probes.push_back(LocateProbeInParts(scene, mesh, probe));
  return model;
}

std::array<Eigen::Vector3d, 4> ElementBendingStrains(const ShellModel& model,
                                                     const ShellState& state,
                                                     int e) {
  const ShellElementState element = ElementStateOf(model, state, e);
  return BendingStrains(model.elements[e], element.positions, element.directors);
}

// The probe in its part: the one it names, else the one it lies on
// (ResolveSelections has refused a probe on two parts).
ProbePoint LocateProbeInParts(const Scene& scene, const Mesh& mesh, const Probe& probe) {
  if (scene.other_parts.empty()) return LocateProbe(mesh, probe);
  const auto parts = FabricParts(scene);
  const auto spans = PartsOf(mesh);
  const auto on = PartsAt(scene, probe.at, DefaultSelectionTolerance(scene.fabric.outline));
  const std::string name = probe.part ? *probe.part : on.empty() ? parts[0]->name : on[0];
  for (std::size_t p = 0; p < parts.size() && p < spans.size(); ++p)
    if (parts[p]->name == name) {
      ProbePoint located = LocateProbe(PartMesh(mesh, spans[p]), probe);
      located.element += spans[p].first_element;
      return located;
    }
  return LocateProbe(mesh, probe);
}

ProbePoint LocateProbe(const Mesh& mesh, const Probe& probe) {
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    double xi, eta;
    if (LocateInElement(mesh, e, probe.at, xi, eta))
      return {probe.name, e, std::clamp(xi, -1.0, 1.0), std::clamp(eta, -1.0, 1.0)};
  }
  // On a curved outline the meshed polygon lies slightly inside: use the nearest node.
  int best = 0;
  double best_d = INFINITY;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d xk = mesh.positions.row(mesh.quads(e, k)).head<2>();
      double d = (xk - Eigen::Vector2d(probe.at[0], probe.at[1])).norm();
      if (d < best_d) {
        best_d = d;
        best = 4 * e + k;
      }
    }
  return {probe.name, best / 4, kQuadNodeXi[best % 4], kQuadNodeEta[best % 4]};
}

Eigen::Vector3d ProbePosition(const ShellModel& model,
                              const ProbePoint& probe,
                              const ShellState& state) {
  Eigen::Vector4d n;
  BilinearShape(probe.xi, probe.eta, n);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k)
    x += n(k) * state.positions.row(model.mesh.quads(probe.element, k)).transpose();
  return x;
}

}  // namespace drape
