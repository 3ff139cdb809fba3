// Which scenes mesh sequencing (core/solve/mesh_sequencing.h) can solve: a
// scene rule, checked by the reader and by the solver; and the factor
// `solver.sequencing: auto` chooses.
#pragma once

#include <optional>
#include <string>

#include "core/model/scene.h"

namespace drape {

// Why `scene` cannot be sequenced with `factor` > 1, or nothing when it can:
// one stage that adds weight or loads (the end state does not depend on the
// path then: nothing moves, nothing is released, no friction), on a
// rectangle meshed by element counts that `factor` divides, at least 2
// coarse elements each way. Nothing to refuse for `factor` 1 or auto.
std::optional<std::string> SequencingRefusal(const Scene& scene, int factor);

// Throws SceneError (key solver.sequencing) with SequencingRefusal's reason.
void CheckSequencing(const Scene& scene, int factor);

// The factor `auto` takes for `scene` (on the mesh it is solved on): 1 (off)
// below kAutoSequencingElements elements or where sequencing cannot serve;
// otherwise the factor that leaves the coarse mesh's shorter side closest to
// kAutoCoarseElements elements, at least kAutoMinCoarseElements.
// Measured (block drape, whole process): 50 × 50 1.25 → 0.56 s with the
// path on 25 × 25; 100 × 100 5.3 s, then 2.8 / 1.9 / 2.3 / 2.5 s on 50, 20,
// 10, 5 elements a side.
inline constexpr int kAutoSequencingElements = 2500;
inline constexpr int kAutoCoarseElements = 20;
inline constexpr int kAutoMinCoarseElements = 10;
int AutoSequencing(const Scene& scene);

// `factor`, with auto resolved for `scene`.
int ChosenSequencing(const Scene& scene, int factor);

}  // namespace drape
