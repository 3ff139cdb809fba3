// The Cusick test read from a scene: where the support disc is, how large,
// and the flat specimen's area, checked so that a measurement means what a
// lab's would.
#pragma once

#include <optional>
#include <stdexcept>

#include "core/measure/drape_coefficient.h"
#include "core/model/scene.h"

namespace drape {

class DrapeTestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The test's options for `scene`. The disc is `support_radius` about
// `centre` (reference x, y), each defaulting to the first support that
// selects a circle. Throws DrapeTestError when the scene has no gravity
// stage (nothing drapes), when no radius is given and no support is a
// circle, or when the disc does not lie inside the part.
DrapeTestOptions DrapeTestFor(const Scene& scene,
                              std::optional<double> support_radius,
                              std::optional<Vec2> centre);

}  // namespace drape
