#include "core/model/sequencing_check.h"

#include <string>
#include <variant>

#include "core/model/scene_error.h"

namespace drape {
namespace {

constexpr const char* kKey = "solver.sequencing";

}  // namespace

void CheckSequencing(const Scene& scene, int factor) {
  if (factor <= 1) return;
  if (scene.stages.size() != 1)
    throw SceneError(kKey,
                     "sequencing solves one stage of weight or loads; this scene has " +
                         std::to_string(scene.stages.size()) + " stages");
  const Stage& stage = scene.stages[0];
  if (stage.kind != StageKind::kGravity && stage.kind != StageKind::kLoad)
    throw SceneError(kKey,
                     "sequencing needs a stage that adds weight or loads: stage '" + stage.name +
                         "' moves or holds, and its end depends on the path");
  if (!stage.moves.empty() || !stage.release.empty())
    throw SceneError(
        kKey,
        "stage '" + stage.name + "' moves or releases something: its end depends on the path");
  if (scene.contact && scene.contact->friction > 0)
    throw SceneError(kKey, "with friction the drape's end depends on the path");
  if (!std::holds_alternative<RectangleOutline>(scene.fabric.outline) ||
      !scene.fabric.mesh.elements)
    throw SceneError(kKey, "sequencing needs a rectangle meshed by element counts");
  const auto [nx, ny] = *scene.fabric.mesh.elements;
  if (nx % factor != 0 || ny % factor != 0 || nx / factor < 2 || ny / factor < 2)
    throw SceneError(kKey,
                     std::to_string(factor) + " must divide the mesh's " + std::to_string(nx) +
                         " × " + std::to_string(ny) + " elements and leave at least 2 each way");
}

}  // namespace drape
