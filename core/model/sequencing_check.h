// Which scenes mesh sequencing (core/solve/mesh_sequencing.h) can solve: a
// scene rule, checked by the reader and by the solver.
#pragma once

#include "core/model/scene.h"

namespace drape {

// Throws SceneError (key solver.sequencing) unless `scene` can be sequenced
// with `factor` > 1: one stage that adds weight or loads (the end state does
// not depend on the path then: nothing moves, nothing is released, no
// friction), on a rectangle meshed by element counts that `factor` divides,
// at least 2 coarse elements each way. Nothing to check for `factor` 1.
void CheckSequencing(const Scene& scene, int factor);

}  // namespace drape
