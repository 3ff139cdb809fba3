#include "core/model/mesh_boundary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace drape {
namespace {

double ReferenceArea(const Mesh& mesh, const std::vector<int>& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto a = mesh.positions.row(loop[i]), b = mesh.positions.row(loop[(i + 1) % loop.size()]);
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return std::abs(twice) / 2;
}

}  // namespace

std::vector<std::vector<int>> BoundaryLoops(const Mesh& mesh) {
  // An edge a→b is on the boundary when no quad runs b→a.
  std::map<std::pair<int, int>, int> uses;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) ++uses[{mesh.quads(e, k), mesh.quads(e, (k + 1) % 4)}];
  std::map<int, int> next;
  for (const auto& [edge, count] : uses)
    if (!uses.count({edge.second, edge.first})) {
      if (!next.emplace(edge.first, edge.second).second)
        throw MeshError("the mesh's boundary passes node " + std::to_string(edge.first) +
                        " twice; its outline is not a set of loops");
    }
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop;
    int node = next.begin()->first;
    while (next.count(node)) {
      loop.push_back(node);
      const int after = next[node];
      next.erase(node);
      node = after;
    }
    loops.push_back(std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(), [&](const auto& a, const auto& b) {
    return ReferenceArea(mesh, a) > ReferenceArea(mesh, b);
  });
  return loops;
}

PatternPiece ProjectedOutline(const Mesh& mesh,
                              const Eigen::Matrix<double, Eigen::Dynamic, 3>& positions,
                              const std::string& name,
                              const std::vector<PiecePoint>& marks) {
  PatternPiece piece;
  piece.name = name;
  const std::vector<std::vector<int>> loops = BoundaryLoops(mesh);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    PieceLine line;
    for (int node : loops[l]) line.push_back({positions(node, 0), positions(node, 1)});
    if (l == 0)
      piece.boundary = std::move(line);
    else
      piece.holes.push_back(std::move(line));
  }
  for (const PiecePoint& mark : marks) {
    Eigen::Index nearest = 0;
    (mesh.positions.leftCols<2>().rowwise() - Eigen::RowVector2d(mark[0], mark[1]))
        .rowwise()
        .squaredNorm()
        .minCoeff(&nearest);
    piece.notches.push_back({positions(nearest, 0), positions(nearest, 1)});
  }
  return piece;
}

}  // namespace drape
