// A closed triangle mesh (OBJ or STL) as an obstacle: a dress form, a shaped
// table. Signed distance by the closest triangle (bounding-volume tree) with
// the sign from angle-weighted pseudo-normals (Bærentzen & Aanæs 2005), so it
// is right at faces, edges and vertices alike.
#pragma once

#include "core/model/obstacle_geometry.h"

#include <filesystem>
#include <memory>
#include <string>

namespace drape {

// Reads and checks the mesh. Throws SceneError (where = `where`, e.g.
// "obstacles[1].mesh.file") when the file cannot be read, is neither OBJ nor
// STL, has a coordinate beyond 1e50 in magnitude, no triangles, degenerate
// triangles, or is not closed (an edge not shared by exactly two triangles) —
// the message says which and where. The file's vertices are then placed in
// the world by `placement` (a scaling that keeps the orientation, a
// rotation, a move).
std::unique_ptr<ObstacleGeometry> MakeTriangleMeshGeometry(
    const std::filesystem::path& file,
    const std::string& where,
    const Eigen::Affine3d& placement = Eigen::Affine3d::Identity());

}  // namespace drape
