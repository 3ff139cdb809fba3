#include "core/model/solver_preset.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace drape {
namespace {

// From the fronts of docs/speed-accuracy.md: the mesh decides the error
// (order ≈ 2 on the strips and the rod drape), and a tolerance of 1e-5 is
// as good as 1e-7 on a scene's own mesh; only long steps (N_p 10) at 1e-3
// or 1e-5 on the finer meshes ended with the element at the gripper turned
// inside out, two elements from the reference (1e-7 never did). N_p pulls
// two ways: 10 is fastest on the strips and the rod, 4 on the diagonal
// fold, whose long steps cross bifurcations that must be switched at.
// N_p = 6 is within 1.6× of the fastest on all three
// (docs/speed-accuracy/np-*.json: strip fold 0.69 s against 0.59 at N_p 7,
// rod 0.31 against 0.20 at 10, diagonal fold 1.64 s against 1.61 at 5 and
// 10.0 at 10), on the same end states. Δλ₀ changed nothing (the
// acceleration takes it over within a few steps), so no preset sets it.
constexpr std::array<PresetDefinition, 3> kPresets{{
    {SolverPreset::kDraft, "draft", 1e-4, 6, 0.5, "half the mesh, tolerance 1e-4: a quick look"},
    {SolverPreset::kBalanced, "balanced", 1e-5, 6, 1.0, "the scene's mesh, tolerance 1e-5"},
    {SolverPreset::kAccurate,
     "accurate",
     1e-7,
     6,
     2.0,
     "twice the mesh, tolerance 1e-7: for results to report"},
}};

}  // namespace

const char* ToString(SolverPreset preset) {
  return Definition(preset).name;
}

std::span<const PresetDefinition> PresetDefinitions() {
  return kPresets;
}

const PresetDefinition& Definition(SolverPreset preset) {
  return kPresets[static_cast<std::size_t>(preset)];
}

std::optional<SolverPreset> PresetNamed(const std::string& name) {
  for (const auto& p : kPresets)
    if (name == p.name) return p.preset;
  return std::nullopt;
}

SolverSettings WithPreset(SolverSettings settings, SolverPreset preset) {
  const PresetDefinition& p = Definition(preset);
  settings.preset = preset;
  settings.tolerance = p.tolerance;
  settings.target_iterations = p.target_iterations;
  settings.mesh_scale = p.mesh_scale;
  return settings;
}

MeshSpec ScaledMesh(const MeshSpec& mesh, double scale) {
  MeshSpec scaled = mesh;
  if (scale == 1) return scaled;
  if (scaled.elements)
    for (int& n : *scaled.elements)
      if (n > 2) n = std::max(1, static_cast<int>(std::lround(n * scale)));
  if (scaled.size) *scaled.size /= scale;
  return scaled;
}

Scene SceneOnSolvedMesh(Scene scene) {
  scene.fabric.mesh = ScaledMesh(scene.fabric.mesh, scene.solver.mesh_scale);
  for (Fabric& part : scene.other_parts) part.mesh = ScaledMesh(part.mesh, scene.solver.mesh_scale);
  scene.solver.mesh_scale = 1;
  return scene;
}

}  // namespace drape
