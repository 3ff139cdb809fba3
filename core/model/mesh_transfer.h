// Comparing the deformed shapes of two runs of the same fabric part meshed
// differently: a run's deformed positions are carried to material points
// given by their reference (x, y), where the other run has its nodes.
//
// Reference coordinates are the x, y of Mesh::positions; z (elevation and
// imperfection) plays no part, since both runs start from the same flat part.
#pragma once

#include <Eigen/Core>

#include "core/model/mesh.h"

namespace drape {

// Where each point of `at` (reference x, y of a flat part) lies on `mesh`
// deformed to `deformed` (#nodes × 3, one row per node of `mesh`): the
// bilinear interpolation of the deformed positions over the quad of `mesh`
// whose reference (x, y) contains the point (inverse bilinear map, Newton on
// (ξ, η)). A point outside every quad (curved outlines meshed differently)
// takes the value at the nearest point of the nearest quad, i.e. on its
// boundary (ξ, η clamped to [0, 1]).
//
// Throws std::invalid_argument when the mesh has no quads, `deformed` does not
// have one row per node, a quad names a node out of range, or a coordinate
// is not finite.
Eigen::MatrixX3d InterpolateDeformed(const Mesh& mesh,
                                     const Eigen::MatrixX3d& deformed,
                                     const Eigen::MatrixX2d& at);

// Distances [m] between the nodes of run A (mesh_a, deformed_a) and the same
// material points on run B (interpolated on mesh_b with InterpolateDeformed):
// the largest, the node of A where it occurs (the first, on a tie), and the
// root mean square over A's nodes.
struct ShapeDistance {
  double max = 0;
  int node = -1;
  double rms = 0;
};

// Throws std::invalid_argument as InterpolateDeformed does, naming the run.
ShapeDistance DeformedDistance(const Mesh& mesh_a,
                               const Eigen::MatrixX3d& deformed_a,
                               const Mesh& mesh_b,
                               const Eigen::MatrixX3d& deformed_b);

}  // namespace drape
