// Quantities of a state evaluated over the elements' Gauss points, for
// reports and colour fields (the solver itself does not need them).
#pragma once

#include "core/solve/shell_model.h"
#include "core/solve/shell_state.h"

namespace drape {

// The largest principal bending curvature |κ| over every Gauss point [1/m]:
// how far a fold has taken the material along its bending law.
double MaxPrincipalCurvature(const ShellModel& model, const ShellState& state);

}  // namespace drape
