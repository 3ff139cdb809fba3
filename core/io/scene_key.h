// Scene keys (docs/format.md §7): a path into a scene file as written —
// members joined by `.`, array elements by `[i]`, as in
// `stages[1].moves[0].path.arc.center[2]`. Studies and plans vary a scene
// through them.
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace drape {

// Sets `key` in the scene document; members missing along the way are made
// (an absent `solver` object), array elements must exist. Throws SceneError
// at `where` naming the key when the path is not a key path or does not lead
// into the scene (an index past the end of an array, a member of a number).
void SetSceneKey(nlohmann::ordered_json& scene,
                 const std::string& key,
                 const nlohmann::json& value,
                 const std::string& where);

// The value at `key`, or null when a member on the way is absent. Throws
// SceneError as SetSceneKey does for a path that is not a key path or an
// index past the end.
nlohmann::ordered_json SceneKeyValue(const nlohmann::ordered_json& scene,
                                     const std::string& key,
                                     const std::string& where);

// Relative `file` references are relative to the scene's folder: made
// absolute, the scene reads from anywhere.
void MakeFilesAbsolute(nlohmann::ordered_json& scene, const std::filesystem::path& scene_dir);

}  // namespace drape
