// Writing a Scene as scene-format JSON with every quantity as an SI number
// (`drape validate --resolved`, the GUI's save, `scene_resolved` in results).
// Reading what this writes gives back an equal Scene.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>

#include "core/model/scene.h"

namespace drape {

// Keys in the order of docs/format.md.
nlohmann::ordered_json SceneToJson(const Scene& scene);
// Indented, short arrays of numbers on one line, ends with a newline.
std::string WriteSceneText(const Scene& scene);
// The same layout for any document (results use it too).
std::string FormatJson(const nlohmann::ordered_json& document);
void WriteScene(const Scene& scene, const std::filesystem::path& file);

// `scene` with its relative file references (Kawabata data, obstacle
// meshes) made absolute from `folder`: to write it somewhere else and have
// it still find them.
Scene WithAbsoluteReferences(const Scene& scene, const std::filesystem::path& folder);

}  // namespace drape
