#include "ui/render/ghost_surface.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>

#include <stdexcept>
#include <string>

#include "ui/render/scene_actors.h"

namespace drape {

vtkSmartPointer<vtkActor> MakeGhostActor() {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->ScalarVisibilityOff();
  auto ghost = vtkSmartPointer<vtkActor>::New();
  ghost->SetMapper(mapper);
  vtkProperty* look = ghost->GetProperty();
  look->SetColor(kGhostColour[0], kGhostColour[1], kGhostColour[2]);
  look->SetOpacity(kGhostOpacity);
  look->SetSpecular(0.0);  // a highlight would hide what is behind
  ghost->PickableOff();    // picks and handles keep hitting the real fabric
  ghost->VisibilityOff();
  return ghost;
}

void PlaceGhost(vtkActor* ghost, const Mesh& mesh, const ShellState& state) {
  if (state.NodeCount() != mesh.NodeCount())
    throw std::invalid_argument("a ghost state of " + std::to_string(state.NodeCount()) +
                                " nodes on a mesh of " + std::to_string(mesh.NodeCount()));
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(FabricSurface(mesh, state.positions, nullptr, 0.0));
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> surface = normals->GetOutput();
  static_cast<vtkPolyDataMapper*>(ghost->GetMapper())->SetInputData(surface);
  ghost->VisibilityOn();
}

}  // namespace drape
