// The history of bending hysteresis (bending_friction.h): the slip the
// yarns' friction has made, committed at each accepted step and carried to
// another mesh.
#pragma once

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"

namespace drape {

// After a step is accepted at `state`: moves each Gauss point's slip to where
// the sliders leave it there, so that the next step starts from this
// history. Does nothing without hysteresis.
void CommitBendingSlip(const ShellModel& model, ShellState& state);

}  // namespace drape
