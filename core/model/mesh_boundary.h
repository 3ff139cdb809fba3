// The edge of a meshed part: its boundary loops, and the outline they make
// wherever the part lies (a lay-down planner wants where a ply's edge
// landed).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/model/mesh.h"
#include "core/model/pattern_piece.h"

namespace drape {

// The mesh's boundary as closed loops of node indices (edges used by one
// quad, in the direction the quad runs them: the outer loop
// counter-clockwise, holes clockwise, seen from +z in the reference). The
// loop enclosing the largest reference area comes first. Requires a mesh
// whose boundary passes each node at most once.
std::vector<std::vector<int>> BoundaryLoops(const Mesh& mesh);

// The part's outline at `positions` (#nodes × 3 [m]) projected on the xy
// plane, as a pattern piece called `name`: the first loop its cut line,
// the others its holes; `marks` (reference xy, e.g. a piece's notches)
// follow the node nearest each into the piece's notches.
PatternPiece ProjectedOutline(const Mesh& mesh,
                              const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                              const std::string& name,
                              const std::vector<PiecePoint>& marks = {});

}  // namespace drape
