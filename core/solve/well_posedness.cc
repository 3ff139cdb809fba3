#include "core/solve/well_posedness.h"

#include <algorithm>
#include <map>

#include "core/model/scene_error.h"
#include "core/model/string_format.h"

namespace drape {
namespace {

std::string Name(const std::string& kind, const std::string& name) {
  return kind + " '" + name + "'";
}

}  // namespace

void CheckHoldsDoNotConflict(const Scene& scene, const ShellModel& model) {
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    const Stage& stage = scene.stages[s];
    std::map<int, std::string> holder;  // node → who holds it still in this stage
    for (const auto& support : model.supports)
      for (int node : support.nodes) holder.emplace(node, Name("support", support.name));
    std::map<int, std::string> mover;
    for (size_t m = 0; m < stage.moves.size(); ++m) {
      const std::string path = "stages[" + std::to_string(s) + "].moves[" + std::to_string(m) + "]";
      for (const auto& g : model.grippers) {
        if (g.name != stage.moves[m].gripper) continue;
        for (int node : g.nodes) {
          if (auto it = holder.find(node); it != holder.end())
            throw SceneError(path,
                             Name("gripper", g.name) + " would move node " + std::to_string(node) +
                                 ", which " + it->second +
                                 " holds in place: it cannot be in two places");
          if (auto it = mover.find(node); it != mover.end())
            throw SceneError(path,
                             Name("gripper", g.name) + " and " + it->second + " both move node " +
                                 std::to_string(node) + " along different paths");
          mover.emplace(node, Name("gripper", g.name));
        }
      }
    }
    for (const auto& g : model.grippers) {
      const bool moved = std::any_of(stage.moves.begin(), stage.moves.end(), [&](const Move& m) {
        return m.gripper == g.name;
      });
      if (moved) continue;
      for (int node : g.nodes)
        if (auto it = mover.find(node); it != mover.end())
          throw SceneError("stages[" + std::to_string(s) + "]",
                           it->second + " moves node " + std::to_string(node) + ", which " +
                               Name("gripper", g.name) +
                               " holds in place: it cannot be in two places");
    }
  }
}

std::string GripperDrivenIntoObstacle(const Scene& scene,
                                      int index,
                                      const ShellModel& model,
                                      const std::vector<bool>& released,
                                      const NodeContact& contact,
                                      const StageLoading& loading,
                                      const ShellState& state) {
  if (!loading.MovesGrippers()) return "";
  constexpr int kSamples = 64;
  ShellState placed = state;
  for (int k = 1; k <= kSamples; ++k) {
    const double lambda = static_cast<double>(k) / kSamples;
    loading.Place(lambda, placed);
    for (size_t g = 0; g < model.grippers.size(); ++g) {
      if (released[g]) continue;
      const auto inside = contact.Penetrations(placed, model.thickness, model.grippers[g].nodes);
      if (inside.empty()) continue;
      return "stage '" + scene.stages[index].name + "': gripper '" + model.grippers[g].name +
             "' is driven into an obstacle: " + inside.front() + Format(" at λ = %.3g", lambda) +
             "; change its path (stages[" + std::to_string(index) +
             "].moves) so that it stays outside";
    }
  }
  return "";
}

}  // namespace drape
