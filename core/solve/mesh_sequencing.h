// Mesh sequencing for a drape (PETSc's grid sequencing, deal.II's step-77):
// the path is followed on a mesh `factor` times coarser in each direction,
// its end is interpolated onto the scene's own mesh, and Newton finishes
// there; the fine state's inertia is checked before it is accepted (the
// solver falls back to the fine path when it is not stable). At 100 × 100
// the factorisations of the path's steps are what a drape costs.
#pragma once

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/model/scene.h"
#include "core/model/sequencing_check.h"

namespace drape {

// The scene on its rectangle's mesh `factor` times coarser, sequencing off.
Scene CoarsenedScene(const Scene& scene, int factor);

// `coarse_state` (of `coarse`) on `fine`'s nodes: each node's displacement
// and director interpolated by the shape functions of the coarse element
// holding its reference point, the director normalised; nodes that supports
// and grippers hold keep their reference position (and their director where
// clamped). Obstacles are placed as in `coarse_state`.
ShellState Prolongate(const ShellModel& coarse,
                      const ShellState& coarse_state,
                      const ShellModel& fine);

}  // namespace drape
