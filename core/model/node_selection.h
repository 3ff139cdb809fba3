// Node selections: which mesh nodes a `select` rule picks, in reference
// (flat) coordinates, independent of the mesh density.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {

// Thrown for a rule that cannot apply to this part (corners of a disk, a
// node index past the last node, a point outside the fabric).
class SelectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Default tolerance [m] when a selection gives none: a millionth of the
// part's size, so only nodes geometrically on the line or edge match.
double DefaultSelectionTolerance(const Outline& outline);

// Sorted, distinct node indices matched by `selection`; may be empty.
std::vector<int> SelectNodes(const Selection& selection, const Mesh& mesh, const Outline& outline);

// Nodes on the mesh boundary (on an edge used by one quad), sorted.
std::vector<int> BoundaryNodes(const Mesh& mesh);

// What a scene's named selections matched, in the order of the file.
struct ResolvedSelection {
  std::string path;  // "supports[0].select"
  std::string name;  // "ridge"
  std::vector<int> nodes;
};

// Applies every selection of the scene (supports, grippers, loads) to the
// mesh and checks the probes lie on the fabric. Throws SceneError naming the
// selection that matched no node or cannot apply.
std::vector<ResolvedSelection> ResolveSelections(const Scene& scene, const Mesh& mesh);

// SelectNodes over a fabric of several parts (Mesh::parts): in the part the
// selection names, else in every part that has what it selects. A point or
// a notch found in two parts that lie over each other is an error asking
// for "part".
std::vector<int> SelectNodesInParts(const Selection& selection,
                                    const Scene& scene,
                                    const Mesh& mesh);

// The names of the parts whose outline holds `at` (within `tol`).
std::vector<std::string> PartsAt(const Scene& scene, const Vec2& at, double tol);

}  // namespace drape
