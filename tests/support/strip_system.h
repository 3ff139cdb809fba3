// A scene's model, the DOFs its supports and grippers fix, the equilibrium
// system over them and its first stage's loading, built as a run builds them
// at the stage's start (SolveRun::StageDofs, SolveRun::Holds) but without a
// ShellSolver: for tests that call the continuation and assembly code
// directly. Built in place (the system and the loading refer to the members
// before them), so it is neither copied nor moved.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/fe/stage_loading.h"
#include "core/model/scene.h"

namespace drape::test {

// The DOFs fixed by every support and gripper of `model`.
inline DofMap HeldDofs(const ShellModel& model) {
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  for (const auto& g : model.grippers)
    for (int node : g.nodes) dofs.FixNode(node, g.fixity);
  return dofs;
}

// Every gripper of `model`, starting from the reference state, on the path
// `stage` moves it along (none: held in place).
inline std::vector<HeldGripper> ReferenceHolds(const ShellModel& model, const Stage& stage) {
  std::vector<HeldGripper> holds;
  for (const auto& gripper : model.grippers) {
    HeldGripper h;
    h.gripper = &gripper;
    for (const auto& m : stage.moves)
      if (m.gripper == gripper.name) h.path = &m.path;
    for (int node : gripper.nodes) {
      h.start_positions.push_back(model.reference.positions.row(node).transpose());
      h.start_rotations.push_back(model.reference.rotations[node]);
    }
    holds.push_back(std::move(h));
  }
  return holds;
}

// A named probe's position in `state`.
inline Eigen::Vector3d ProbeAt(const ShellModel& model,
                               const std::string& name,
                               const ShellState& state) {
  for (const auto& p : model.probes)
    if (p.name == name) return ProbePosition(model, p, state);
  return Eigen::Vector3d::Constant(NAN);
}

struct SceneSystem {
  explicit SceneSystem(const Scene& s) : SceneSystem(s, BuildShellModel(s)) {}
  // On a model built from a mesh of the caller's (BuildShellModel(s, mesh)).
  SceneSystem(const Scene& s, ShellModel m)
      : scene(s),
        model(std::move(m)),
        dofs(HeldDofs(model)),
        system(model, dofs),
        loading(model, scene.stages.at(0), ReferenceHolds(model, scene.stages.at(0)), 0.0, 0.0) {}
  SceneSystem(const SceneSystem&) = delete;
  SceneSystem& operator=(const SceneSystem&) = delete;

  // ‖R‖ over the free DOFs at (state, λ), assembled afresh.
  double ResidualNorm(const ShellState& state, double lambda) {
    system.Assemble(state, /*with_tangent=*/false);
    return system.Residual(loading.External(lambda, state)).norm();
  }

  Scene scene;  // the stage's paths live here
  ShellModel model;
  DofMap dofs;
  EquilibriumSystem system;
  StageLoading loading;
};

}  // namespace drape::test
