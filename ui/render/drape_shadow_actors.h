// The drapemeter's view (the Cusick test, docs/cusick.md): the shadow the
// state casts along gravity, filled on a plane under the part, with the
// support disc's rim and the flat specimen's rim drawn over it. The numbers
// come from core/measure, as `drape measure` computes them. Internal to
// ui/render.
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Geometry>

#include <optional>
#include <vector>

#include "core/fe/shell_state.h"
#include "core/measure/drape_coefficient.h"
#include "core/model/mesh.h"
#include "core/model/scene.h"

class vtkActor;
class vtkRenderer;

namespace drape {

// The test a scene meshed as `mesh` is, when it is one (a gravity stage and
// a support that selects a circle, docs/cusick.md); nullopt for any other.
std::optional<DrapeTestOptions> DrapemeterTestOf(const Scene& scene, const Mesh& mesh);

class DrapeShadowActors {
 public:
  // Adds the actors to `renderer`; the shadow's plane lies under `bounds`
  // (every frame of the run) along gravity.
  DrapeShadowActors(vtkRenderer* renderer,
                    const DrapeTestOptions& test,
                    const Eigen::AlignedBox3d& bounds);

  // Measures `state` and moves the shadow there; returns the measurement
  // (for the overlay's drape coefficient and node count).
  DrapeMeasurement Place(const Mesh& mesh, const ShellState& state);

 private:
  Eigen::Vector3d OnPlane(const Eigen::Vector2d& p, double depth) const;
  std::vector<Eigen::Vector3d> Rim(double radius, double depth) const;

  DrapeTestOptions test_;
  ShadowPlane plane_;
  double shadow_depth_ = 0;  // along gravity from the disc's centre [m]
  vtkSmartPointer<vtkActor> shadow_, disc_rim_, specimen_rim_;
};

}  // namespace drape
