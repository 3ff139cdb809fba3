// The Cusick test read from a scene: where the support disc is, how large,
// and the flat specimen's area, checked so that a measurement means what a
// lab's would.
#pragma once

#include <optional>
#include <stdexcept>

#include "core/measure/drape_coefficient.h"
#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {

class DrapeTestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The test's options for `scene` meshed as `mesh` (its reference state).
// The disc is `support_radius` about `centre` (reference x, y), each
// defaulting to the first support that selects a circle. The specimen's
// area is the flat mesh's, so that the flat specimen's DC is 1 exactly (a
// disk's mesh is a polygon inside its circle). Throws DrapeTestError when the scene has no gravity
// stage (nothing drapes), when no radius is given and no support is a
// circle, or when the disc does not lie inside the part.
DrapeTestOptions DrapeTestFor(const Scene& scene,
                              const Mesh& mesh,
                              std::optional<double> support_radius,
                              std::optional<Vec2> centre);

}  // namespace drape
