#include "core/io/material_library.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "core/io/json_cursor.h"
#include "core/io/resource_dir.h"
#include "core/model/scene_error.h"

namespace drape {
namespace fs = std::filesystem;

namespace {
constexpr int kMaterialFormatVersion = 1;
}

std::vector<fs::path> MaterialLibraryDirs(const fs::path& scene_directory) {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("DRAPE_MATERIALS")) {
    std::stringstream list(env);
    std::string dir;
    while (std::getline(list, dir, ':'))
      if (!dir.empty()) dirs.emplace_back(dir);
  }
  dirs.push_back(scene_directory / "materials");
  dirs.push_back(scene_directory / ".." / "materials");
  dirs.push_back(ResourceDir() / "materials");
  for (auto& d : dirs) d = d.lexically_normal();
  return dirs;
}

std::optional<fs::path> FindLibraryMaterial(std::string_view name,
                                            const std::vector<fs::path>& dirs) {
  // A name, not a path: nothing outside the library directories is found.
  if (name.empty() || name.find_first_of("/\\") != std::string_view::npos || name[0] == '.')
    return std::nullopt;
  std::error_code ec;
  for (const auto& dir : dirs) {
    const fs::path file = dir / (std::string(name) + ".json");
    if (fs::is_regular_file(file, ec)) return file;
  }
  return std::nullopt;
}

std::vector<std::string> LibraryMaterialNames(const std::vector<fs::path>& dirs) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& dir : dirs) {
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.is_regular_file() && entry.path().extension() == ".json")
        names.insert(entry.path().stem().string());
  }
  return {names.begin(), names.end()};
}

LibraryMaterial ReadLibraryMaterial(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw SceneError(file.string(), "cannot open the library material");
  LibraryMaterial entry;
  entry.file = file;
  entry.document = std::make_shared<nlohmann::json>();
  try {
    *entry.document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(file.string(), std::string("not valid JSON: ") + e.what());
  }
  // Errors name the file, then the key in it.
  try {
    const JsonCursor root(*entry.document, "");
    root.ExpectObject({"drape_material", "name", "source", "description", "material"});
    auto version = root["drape_material"];
    if (version.Integer() != kMaterialFormatVersion)
      version.Fail("unsupported material format version " + std::to_string(version.Integer()) +
                   "; this program reads version " + std::to_string(kMaterialFormatVersion));
    if (auto c = root.Find("name")) entry.name = c->String();
    if (auto c = root.Find("source")) entry.source = c->String();
    if (auto c = root.Find("description")) entry.description = c->String();
    auto material = root["material"];
    if (!material.value().is_object()) material.Fail("expected an object (a scene's material)");
    if (material.Has("library"))
      material["library"].Fail("a library material cannot refer to another");
    entry.material = &material.value();
  } catch (const SceneError& e) {
    throw SceneError(file.string() + (e.where().empty() ? "" : ": " + e.where()), e.message());
  }
  return entry;
}

}  // namespace drape
