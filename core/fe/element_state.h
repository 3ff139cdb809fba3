// An element's four nodes gathered from the shell's state, in the form the
// element kernel takes them (core/mechanics/shell_element.h).
#pragma once

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/mechanics/shell_element.h"

namespace drape {

ShellElementState ElementStateOf(const ShellModel& model, const ShellState& state, int e);

}  // namespace drape
