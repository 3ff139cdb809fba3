// Reading scene files (format version 1, docs/format.md) into a Scene.
//
// Every error is a SceneError naming the JSON path of the offending key and
// what was expected, or the line and column where a file stops being JSON.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string_view>

#include "core/model/scene.h"

namespace drape {

// Parses scene text. `base_directory` resolves relative file references
// (Kawabata curves, obstacle meshes), which must exist.
Scene ParseScene(std::string_view text, const std::filesystem::path& base_directory = ".");

// Reads a scene file; relative references are resolved next to it.
Scene ReadScene(const std::filesystem::path& file);

// The JSON document form, for callers that already hold one.
Scene SceneFromJson(const nlohmann::json& document,
                    const std::filesystem::path& base_directory = ".");

}  // namespace drape
