// Accuracy presets (`solver.preset`): the mesh density, tolerance and N_p
// that the measured speed–accuracy fronts (docs/speed-accuracy.md) showed to
// be efficient, under one name. A preset is a base: any key the scene's
// `solver` object also gives overrides the preset's value, as clang-format's
// BasedOnStyle does.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "core/model/scene.h"

namespace drape {

struct PresetDefinition {
  SolverPreset preset;
  const char* name;
  double tolerance;       // ‖R‖/‖R₀‖
  int target_iterations;  // N_p
  double mesh_scale;      // elements per direction, relative to fabric.mesh
  const char* purpose;    // one line for menus and --help
};

// draft, balanced, accurate: in that order.
std::span<const PresetDefinition> PresetDefinitions();
const PresetDefinition& Definition(SolverPreset preset);
// The preset of that name; empty when there is none.
std::optional<SolverPreset> PresetNamed(const std::string& name);

// `settings` with the preset's tolerance, N_p and mesh scale, and the preset
// recorded; every other setting kept.
SolverSettings WithPreset(SolverSettings settings, SolverPreset preset);

// `mesh` with `scale` times the elements in each direction that has more
// than two (a strip's width of one or two elements stays), at least one;
// a target element size is divided by `scale`.
MeshSpec ScaledMesh(const MeshSpec& mesh, double scale);

// The scene as it is solved: its fabric meshed at `solver.mesh_scale` times
// its `fabric.mesh`, and a mesh scale of 1 (so that solving, coarsening and
// sequencing all start from the mesh that is solved).
Scene SceneOnSolvedMesh(Scene scene);

}  // namespace drape
