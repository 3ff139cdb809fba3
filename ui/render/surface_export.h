// The deformed surface of a run written for other tools: VTK XML (.vtu per
// step and a .pvd collection with time = step, so ParaView plays the run),
// OBJ, PLY and STL (optionally as a closed solid of the fabric's thickness,
// to print a fold) and CSV of nodes with their fields.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"

namespace drape {

enum class SurfaceFormat { kVtu, kObj, kPly, kStl, kCsv };

struct ExportedStep {
  const ShellState* state = nullptr;
  int step = 0;    // 0: the reference state
  int stage = -1;  // index in the scene's stages; −1 for the reference
  double lambda = 0;
};

// Writes one file per step into `directory` (created), named
// step_NNNN.<ext>, plus run.pvd for VTU (time = stage index + λ, since λ
// restarts in every stage). `solid` (STL, OBJ, PLY): both faces
// h apart and the rim between them, a closed surface. Returns the files
// written; throws std::runtime_error naming a file that cannot be written.
// `progress` (optional) hears (steps written, steps) after each step; when
// it returns false the export stops there, keeping (and for VTU
// collecting) the steps written.
std::vector<std::filesystem::path> ExportSurfaces(
    const ShellModel& model,
    const std::vector<ExportedStep>& steps,
    SurfaceFormat format,
    const std::filesystem::path& directory,
    bool solid = false,
    const std::function<bool(int done, int all)>& progress = nullptr);

}  // namespace drape
