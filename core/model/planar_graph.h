// A polygon with what its mesh must follow inside it, as one planar
// straight-line graph for the mesher: cut-outs, lines that become element
// edges (a pattern's fold lines and placement marks) and points that become
// nodes (notches, drill holes).
//
// Gmsh embeds a curve or point in a surface only where it meets the boundary
// at a shared point, and two embedded curves only where they share an end.
// So a feature point near the boundary is moved onto it (the boundary edge
// split there), lines are split where they cross, and every vertex within
// `merge` of another is one vertex.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace drape {

// An open polyline inside the part or ending on its boundary; `name` is
// what errors call it ("internal line 2").
struct FeatureLine {
  std::vector<Eigen::Vector2d> points;
  std::string name;
};
// A point inside the part or on its boundary.
struct FeaturePoint {
  Eigen::Vector2d at;
  std::string name;
};

struct MeshFeatures {
  // Simple polygons inside the outline, apart from it and from each other.
  std::vector<std::vector<Eigen::Vector2d>> holes = {};
  std::vector<FeatureLine> lines = {};
  std::vector<FeaturePoint> points = {};
};

struct PlanarGraph {
  std::vector<Eigen::Vector2d> vertices;
  // The outline's loop, then each hole's: vertex indices in order, with the
  // vertices where lines and points meet them inserted.
  std::vector<std::vector<int>> loops;
  // Segments to embed in the surface (no two cross; they meet only at
  // vertices).
  std::vector<std::array<int, 2>> segments;
  // Vertices to embed that lie on no loop and no segment.
  std::vector<int> points;
};

// Builds the graph of a validated outline and holes (MeshPolygon checks
// them). A line vertex or point within `snap` of the boundary, of a line or
// of a vertex is moved onto it: closer than that, the mesh would need
// elements far smaller than its size. A line shorter than `snap` is left
// out. Throws MeshError naming the line or point that leaves the part,
// crosses its boundary or runs along another line.
PlanarGraph BuildPlanarGraph(const std::vector<Eigen::Vector2d>& outline,
                             const MeshFeatures& features,
                             double snap);

}  // namespace drape
