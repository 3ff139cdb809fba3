// The materials library: named fabric materials, one JSON file each
// (resources/materials/<name>.json, format in docs/format.md), that a scene
// uses with "material": {"library": "<name>", …keys that override…}.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drape {

// Where names are looked up, in order: each directory of the environment
// variable DRAPE_MATERIALS (colon-separated), `scene_directory`/materials,
// `scene_directory`/../materials, and the library that ships with the
// program (ResourceDir()/materials).
std::vector<std::filesystem::path> MaterialLibraryDirs(
    const std::filesystem::path& scene_directory);

// The file of `name` (`<name>.json` in the first directory that has it).
std::optional<std::filesystem::path> FindLibraryMaterial(
    std::string_view name, const std::vector<std::filesystem::path>& dirs);

// Every name found in `dirs`, sorted, each once (the first directory wins).
std::vector<std::string> LibraryMaterialNames(const std::vector<std::filesystem::path>& dirs);

// A library file parsed: throws SceneError (where: the file and key) for a
// file that is not JSON, not format version 1, or misses `material`.
struct LibraryMaterial {
  std::filesystem::path file;
  std::string name;                          // what the file calls itself
  std::string source;                        // where its numbers come from
  std::string description;                   // assumptions, valid range
  const nlohmann::json* material = nullptr;  // into `document`
  std::shared_ptr<nlohmann::json> document;
};
LibraryMaterial ReadLibraryMaterial(const std::filesystem::path& file);

}  // namespace drape
