#include "core/io/library_fabric.h"

#include <nlohmann/json.hpp>

#include "core/io/scene_reader.h"

namespace drape {

// A one-element scene naming the fabric, read as any other.
Material LibraryFabric(const std::string& name, const std::filesystem::path& scene_directory) {
  const nlohmann::json scene = {
      {"drape_scene", 1},
      {"fabric",
       {{"outline", {{"rectangle", {{"size", {1, 1}}}}}}, {"mesh", {{"elements", {1, 1}}}}}},
      {"material", {{"library", name}}},
      {"stages", {{{"name", "show"}, {"kind", "hold"}}}}};
  return SceneFromJson(scene, scene_directory).material;
}

}  // namespace drape
