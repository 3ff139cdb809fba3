#include "core/plan/path_parameters.h"

#include <variant>

namespace drape {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

void AddVector(std::vector<PathParameter>& out,
               const std::string& key,
               const std::string& label,
               const Vec3& v) {
  for (int i = 0; i < 3; ++i)
    out.push_back(
        {key + "[" + std::to_string(i) + "]", label + " " + kAxes[i], v[i], dim::kLength});
}

}  // namespace

std::vector<PathParameter> PathParameters(const Scene& scene) {
  std::vector<PathParameter> out;
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    const Stage& stage = scene.stages[s];
    for (size_t m = 0; m < stage.moves.size(); ++m) {
      const Move& move = stage.moves[m];
      const std::string key =
          "stages[" + std::to_string(s) + "].moves[" + std::to_string(m) + "].path";
      const std::string who =
          stage.name + ": " + (move.gripper.empty() ? move.obstacle : move.gripper) + ", ";
      if (const auto* line = std::get_if<LinePath>(&move.path)) {
        AddVector(out, key + ".line.by", who + "line by", line->by);
      } else if (const auto* arc = std::get_if<ArcPath>(&move.path)) {
        AddVector(out, key + ".arc.center", who + "arc centre", arc->center);
        out.push_back(
            {key + ".arc.angle_deg", who + "arc angle (deg)", arc->angle_deg, dim::kNone});
      } else if (const auto* frames = std::get_if<KeyframesPath>(&move.path)) {
        for (size_t k = 0; k < frames->points.size(); ++k)
          AddVector(out,
                    key + ".keyframes.points[" + std::to_string(k) + "]",
                    who + "keyframe " + std::to_string(k + 1),
                    frames->points[k]);
      }
    }
  }
  return out;
}

}  // namespace drape
