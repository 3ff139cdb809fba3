// Quadrilateral meshes of the flat fabric part in its reference state.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <vector>

#include "core/model/planar_graph.h"

namespace drape {

// Bilinear-quad mesh. Node numbering and element numbering are deterministic
// (rows of increasing y, then increasing x), and every quad is numbered
// counter-clockwise seen from +z, so its normal points along +z.
// The nodes and elements of one part of a mesh made of several (a fabric
// cut as separate pieces): consecutive ranges, part after part.
struct MeshPart {
  int first_node = 0, nodes = 0;
  int first_element = 0, elements = 0;
};

struct Mesh {
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;  // #nodes × 3, reference positions [m]
  Eigen::Matrix<int, Eigen::Dynamic, 4> quads;         // #elements × 4 node indices
  // Empty for a mesh of one part; else each part's ranges, covering all.
  std::vector<MeshPart> parts;

  int NodeCount() const { return static_cast<int>(positions.rows()); }
  int ElementCount() const { return static_cast<int>(quads.rows()); }
};

// The mesh's parts: `parts`, or the whole mesh as one.
std::vector<MeshPart> PartsOf(const Mesh& mesh);
// Part `part` of `mesh` as a mesh of its own (node k of it is node
// first_node + k of `mesh`).
Mesh PartMesh(const Mesh& mesh, const MeshPart& part);
// The meshes of parts, one after another, as one mesh with its parts.
Mesh JoinedMesh(const std::vector<Mesh>& parts);

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Structured nx × ny mesh of the rectangle size_x × size_y centred at `center`,
// lying in the plane z = elevation. Throws MeshError for non-positive sizes or counts.
Mesh MeshRectangle(
    double size_x, double size_y, const Eigen::Vector2d& center, int nx, int ny, double elevation);

// All-quad unstructured meshes made by Gmsh (quad recombination), with target
// element edge `element_size`, lying in the plane z = elevation. Throws MeshError.
Mesh MeshDisk(double radius, const Eigen::Vector2d& center, double element_size, double elevation);
// `outline` is a simple polygon, either orientation, not closed (last != first);
// each of `features.holes` likewise, inside it and apart from it and from
// each other. Element edges follow `features.lines` and a node sits on each
// of `features.points`, moved onto the boundary or a line within a quarter
// of element_size of it (planar_graph.h).
Mesh MeshPolygon(const std::vector<Eigen::Vector2d>& outline,
                 double element_size,
                 double elevation,
                 const MeshFeatures& features = {});

// Sum of the quads' areas projected on the xy plane [m²] (signed: a quad
// numbered clockwise counts negative).
double ProjectedArea(const Mesh& mesh);

// The mean length of the quads' edges (each quad's four, shared edges
// counted twice) [m].
double MeanEdgeLength(const Mesh& mesh);

// Shape measures over all quads, for tests and for the `validate` summary,
// taken on the quads' projection on the xy plane.
struct MeshQuality {
  double min_angle_deg = 0;     // smallest interior angle of any quad
  double max_angle_deg = 0;     // largest interior angle of any quad
  double max_aspect_ratio = 0;  // longest / shortest edge of any quad
  double min_signed_area = 0;   // smallest quad area (negative: inverted quad)
};
MeshQuality MeasureQuality(const Mesh& mesh);

}  // namespace drape
