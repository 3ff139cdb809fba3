// A preview's ghost (issue 20): the state of a draft solve drawn as a
// translucent, uniformly coloured surface over the shown result, on the
// draft's own (coarser) mesh. No colour field: the ghost shows where the
// fabric will go, the shown result keeps its field. Internal to ui/render.
#pragma once

#include <vtkSmartPointer.h>

#include "core/fe/shell_state.h"
#include "core/model/mesh.h"

class vtkActor;

namespace drape {

// Light blue at opacity 0.35: the fabric's orange and violet behind it
// still read, and the ghost does not pass for either face.
constexpr double kGhostColour[3] = {0.55, 0.72, 0.95};
constexpr double kGhostOpacity = 0.35;

// An actor with the ghost's look and no geometry (hidden until placed).
vtkSmartPointer<vtkActor> MakeGhostActor();

// The actor's surface: `state` on `mesh` (copied: neither need outlive the call).
void PlaceGhost(vtkActor* ghost, const Mesh& mesh, const ShellState& state);

}  // namespace drape
