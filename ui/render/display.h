// Debian's VTK renders through X (GLX), even offscreen: without a display
// it aborts. Rendering commands ask first and say what to do instead.
#pragma once

#include <string>

namespace drape {

// Empty when an X display can be opened; otherwise the one message to show.
std::string DisplayProblem();

}  // namespace drape
