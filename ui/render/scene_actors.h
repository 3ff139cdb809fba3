// The geometry the frame renderer draws, as VTK poly data: the fabric's
// surface, the obstacles' shapes, the grippers' paths. Internal to ui/render.
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/mesh.h"
#include "core/model/scene.h"

class vtkActor;
class vtkPolyData;

namespace drape {

// The midsurface, one quad per element; with `offset` ≠ 0 the surface moved
// by `offset` along the nodal directors.
vtkSmartPointer<vtkPolyData> FabricSurface(
    const Mesh& mesh,
    const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
    const Eigen::Matrix<double, Eigen::Dynamic, 3>* directors,
    double offset);

// An obstacle in its scene placement. Infinite shapes (planes, infinite
// cylinders) are cut to `bounds` grown by a margin. Throws
// std::runtime_error for a mesh file VTK cannot read.
vtkSmartPointer<vtkPolyData> ObstacleSurface(const Obstacle& obstacle,
                                             const Eigen::AlignedBox3d& bounds);

// An actor drawing `data` through a poly-data mapper of its own.
vtkSmartPointer<vtkActor> ActorOf(vtkPolyData* data);

// The path each gripper's held nodes' centroid follows over the stages, one
// polyline per move (in order), starting from the reference positions.
std::vector<std::vector<Eigen::Vector3d>> GripperPaths(const Scene& scene, const ShellModel& model);

}  // namespace drape
