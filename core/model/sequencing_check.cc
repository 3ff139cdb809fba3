#include "core/model/sequencing_check.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <variant>

#include "core/model/scene_error.h"

namespace drape {

std::optional<std::string> SequencingRefusal(const Scene& scene, int factor) {
  if (factor <= 1) return std::nullopt;
  // Each reason names the factor, as solver.sequencing gives it.
  const std::string sequencing = "sequencing " + std::to_string(factor);
  if (scene.stages.size() != 1)
    return sequencing + " solves one stage of weight or loads; this scene has " +
           std::to_string(scene.stages.size()) + " stages";
  const Stage& stage = scene.stages[0];
  if (stage.kind != StageKind::kGravity && stage.kind != StageKind::kLoad)
    return sequencing + " needs a stage that adds weight or loads: stage '" + stage.name +
           "' moves or holds, and its end depends on the path";
  if (!stage.moves.empty() || !stage.release.empty())
    return sequencing + " cannot solve stage '" + stage.name +
           "': it moves or releases something, and its end depends on the path";
  if (scene.contact && scene.contact->friction > 0)
    return sequencing + " needs contact without friction: with friction the drape's end " +
           "depends on the path";
  if (!scene.other_parts.empty())
    return sequencing + " needs a fabric of one part; this one has " +
           std::to_string(scene.other_parts.size() + 1);
  if (!std::holds_alternative<RectangleOutline>(scene.fabric.outline) ||
      !scene.fabric.mesh.elements)
    return sequencing + " needs a rectangle meshed by element counts";
  const auto [nx, ny] = *scene.fabric.mesh.elements;
  if (nx % factor != 0 || ny % factor != 0 || nx / factor < 2 || ny / factor < 2)
    return std::to_string(factor) + " must divide the mesh's " + std::to_string(nx) + " × " +
           std::to_string(ny) + " elements and leave at least 2 each way";
  return std::nullopt;
}

void CheckSequencing(const Scene& scene, int factor) {
  if (auto why = SequencingRefusal(scene, factor)) throw SceneError("solver.sequencing", *why);
}

int AutoSequencing(const Scene& scene) {
  if (!scene.fabric.mesh.elements) return 1;
  const auto [nx, ny] = *scene.fabric.mesh.elements;
  if (nx * ny < kAutoSequencingElements) return 1;
  const int shorter = std::min(nx, ny);
  int best = 1;
  for (int factor = 2; shorter / factor >= kAutoMinCoarseElements; ++factor) {
    if (SequencingRefusal(scene, factor)) continue;
    if (best == 1 || std::abs(shorter / factor - kAutoCoarseElements) <
                         std::abs(shorter / best - kAutoCoarseElements))
      best = factor;
  }
  return best;
}

int ChosenSequencing(const Scene& scene, int factor) {
  return factor == kAutoSequencing ? AutoSequencing(scene) : factor;
}

}  // namespace drape
