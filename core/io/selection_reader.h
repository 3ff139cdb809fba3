// A selection (docs/format.md §3.4) read outside a scene file — a plan's
// region — with the scene reader's rules and messages.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>

#include "core/model/scene.h"

namespace drape {

// `path` is the key path the messages name (`objective.flat.select`);
// `scene` gives the parts a `part` may name. Throws SceneError.
Selection ReadSelection(const nlohmann::json& value, const std::string& path, const Scene& scene);

}  // namespace drape
