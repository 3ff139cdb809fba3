// A library fabric as a scene that names it gets it ("material":
// {"library": NAME}), read by the scene reader's own rules: what the
// library's cards and `drape material show` describe.
#pragma once

#include <filesystem>
#include <string>

#include "core/model/scene.h"

namespace drape {

// Throws SceneError when the name is not in the library (looked up from
// `scene_directory` as a scene there would) or its entry is wrong.
Material LibraryFabric(const std::string& name, const std::filesystem::path& scene_directory);

}  // namespace drape
