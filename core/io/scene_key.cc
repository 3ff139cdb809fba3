#include "core/io/scene_key.h"

#include <vector>

#include "core/model/scene_error.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

// `stages[1].initial_increment` → ("stages", {1}), ("initial_increment", {}).
struct PathStep {
  std::string name;
  std::vector<size_t> indices;
};

std::vector<PathStep> ParsePath(const std::string& key, const std::string& where) {
  std::vector<PathStep> steps;
  size_t at = 0;
  auto fail = [&](const std::string& why) {
    throw SceneError(where,
                     "'" + key + "' is not a scene key path (" + why +
                         "); write it as in fabric.mesh.elements or "
                         "stages[1].initial_increment");
  };
  while (at <= key.size()) {
    const size_t end = std::min(key.find('.', at), key.size());
    const std::string token = key.substr(at, end - at);
    const size_t bracket = token.find('[');
    PathStep step{token.substr(0, bracket), {}};
    if (step.name.empty()) fail("an empty name");
    for (size_t b = bracket; b != std::string::npos;) {
      const size_t close = token.find(']', b);
      if (close == std::string::npos || close == b + 1) fail("an index without its number");
      const std::string digits = token.substr(b + 1, close - b - 1);
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6)
        fail("index '" + digits + "' is not a whole number");
      step.indices.push_back(std::stoul(digits));
      b = close + 1 < token.size() ? close + 1 : std::string::npos;
      if (b != std::string::npos && token[b] != '[') fail("text after an index");
    }
    steps.push_back(std::move(step));
    at = end + 1;
  }
  return steps;
}

// Walks `key` from `scene`; `make` creates absent members (and the objects
// that hold them). Returns null when a member is absent and not made.
template <typename Json>
Json* Walk(Json& scene, const std::string& key, const std::string& where, bool make) {
  Json* node = &scene;
  std::string reached;
  for (const PathStep& step : ParsePath(key, where)) {
    if (make && node->is_null()) *node = Json::object();
    if (!node->is_object())
      throw SceneError(where,
                       "'" + key + "': the scene's " + (reached.empty() ? "document" : reached) +
                           " is not an object");
    reached += (reached.empty() ? "" : ".") + step.name;
    if (!make && !node->contains(step.name)) return nullptr;
    node = &(*node)[step.name];
    for (size_t i : step.indices) {
      reached.append("[").append(std::to_string(i)).append("]");
      if (!node->is_array() || i >= node->size())
        throw SceneError(
            where,
            "'" + key + "': the scene has no " + reached +
                (node->is_array() ? " (it has " + std::to_string(node->size()) + ")" : ""));
      node = &(*node)[i];
    }
  }
  return node;
}

}  // namespace

void SetSceneKey(ordered_json& scene,
                 const std::string& key,
                 const json& value,
                 const std::string& where) {
  *Walk(scene, key, where, true) = value;
}

ordered_json SceneKeyValue(const ordered_json& scene,
                           const std::string& key,
                           const std::string& where) {
  ordered_json copy = scene;  // Walk's operator[] needs a mutable document
  const ordered_json* node = Walk(copy, key, where, false);
  return node ? *node : ordered_json();
}

void MakeFilesAbsolute(ordered_json& node, const fs::path& scene_dir) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it.key() == "file" && it.value().is_string()) {
        const fs::path p = it.value().get<std::string>();
        if (p.is_relative()) it.value() = (scene_dir / p).lexically_normal().string();
      } else {
        MakeFilesAbsolute(it.value(), scene_dir);
      }
    }
  } else if (node.is_array()) {
    for (auto& element : node) MakeFilesAbsolute(element, scene_dir);
  }
}

}  // namespace drape
