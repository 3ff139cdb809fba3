// The smallest valid scene the reader tests edit into a wrong one: a
// 20 × 2 cm strip clamped at its left edge, hanging under its weight, as
// the scene file's JSON.
#pragma once

#include <nlohmann/json.hpp>

namespace drape::test {

inline nlohmann::json MinimalSceneJson() {
  return nlohmann::json::parse(R"({
    "drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": ["20 cm", "2 cm"]}}, "mesh": {"elements": [8, 1]}},
    "material": {"thickness": "0.5 mm", "areal_weight": 2.0, "youngs_modulus": "1 MPa",
                 "poisson_ratio": 0.3},
    "supports": [{"name": "root", "select": {"edge": "left"}, "fix": "clamp"}],
    "stages": [{"name": "SW", "kind": "gravity"}]
  })");
}

}  // namespace drape::test
