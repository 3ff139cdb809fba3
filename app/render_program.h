// The commands that draw — render, animate, export and run --render-every —
// run in a second program, drape-vtk: the same commands linked with VTK.
// `drape` itself is not linked with VTK, so that its other commands do not
// resolve VTK's (and through it MPI's and X11's) symbols at start-up:
// measured 30 ms of a 60 ms heavy-cantilever run (docs/performance.md).
#pragma once

namespace drape::app {

// Keeps the command line for RunInRenderProgram.
void RememberCommandLine(int argc, char** argv);

// Replaces this process by drape-vtk with the same command line (found next
// to this program, or in ../libexec/drape when installed). Returns only when
// that fails: prints why, naming `command`, and returns exit code 1.
int RunInRenderProgram(const char* command);

}  // namespace drape::app
