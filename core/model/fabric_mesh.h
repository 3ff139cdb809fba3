// The reference mesh of a scene's fabric: outline + mesh density + imperfection.
#pragma once

#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {

// Meshes the outline (structured for rectangles, Gmsh quads otherwise), lifts
// it to `elevation` and adds the imperfection. Throws SceneError naming
// `fabric.mesh` or `fabric.outline` when the outline cannot be meshed.
Mesh MeshFabric(const Fabric& fabric);

// Every part of the scene's fabric meshed by MeshFabric and joined, part
// after part (Mesh::parts); a fabric of one part is MeshFabric's mesh.
// Errors name the part's key (`fabric[1].outline`).
Mesh MeshFabricParts(const Scene& scene);

// The flat plane's height of each node (its part's elevation) [m].
Eigen::VectorXd PartElevations(const Scene& scene, const Mesh& mesh);

// Element counts [nx, ny] a rectangle gets for a target element edge.
std::array<int, 2> RectangleElementCounts(const RectangleOutline& rectangle, double element_size);

}  // namespace drape
