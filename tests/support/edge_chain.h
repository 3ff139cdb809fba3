// Whether a straight line in a flat mesh is followed by element edges: the
// nodes on it, in order along it, from one end to the other, each joined to
// the next by an edge of some quad.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/model/mesh.h"

namespace drape::test {

inline bool IsQuadEdge(const Mesh& mesh, int i, int j) {
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.quads(e, k), b = mesh.quads(e, (k + 1) % 4);
      if ((a == i && b == j) || (a == j && b == i)) return true;
    }
  return false;
}

// The nodes within `tol` of segment ab, ordered from a to b.
inline std::vector<int> NodesAlong(const Mesh& mesh,
                                   const Eigen::Vector2d& a,
                                   const Eigen::Vector2d& b,
                                   double tol) {
  std::vector<std::pair<double, int>> on;
  const Eigen::Vector2d ab = b - a;
  for (int n = 0; n < mesh.NodeCount(); ++n) {
    const Eigen::Vector2d p = mesh.positions.row(n).head<2>().transpose();
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    if ((a + t * ab - p).norm() <= tol) on.push_back({t, n});
  }
  std::sort(on.begin(), on.end());
  std::vector<int> nodes;
  for (const auto& [t, n] : on) nodes.push_back(n);
  return nodes;
}

// Expects segment ab to be a chain of element edges with a node at each
// end; returns the chain's nodes.
inline std::vector<int> ExpectEdgeChain(const Mesh& mesh,
                                        const Eigen::Vector2d& a,
                                        const Eigen::Vector2d& b,
                                        double tol) {
  const std::vector<int> nodes = NodesAlong(mesh, a, b, tol);
  EXPECT_GE(nodes.size(), 2u);
  if (nodes.size() < 2) return nodes;
  EXPECT_LE((mesh.positions.row(nodes.front()).head<2>().transpose() - a).norm(), tol);
  EXPECT_LE((mesh.positions.row(nodes.back()).head<2>().transpose() - b).norm(), tol);
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
    EXPECT_TRUE(IsQuadEdge(mesh, nodes[i], nodes[i + 1]))
        << "nodes " << nodes[i] << " and " << nodes[i + 1] << " on the line are not an edge";
  return nodes;
}

// The distance from p to the mesh's nearest node.
inline double DistanceToNearestNode(const Mesh& mesh, const Eigen::Vector2d& p) {
  double best = 1e300;
  for (int n = 0; n < mesh.NodeCount(); ++n)
    best = std::min(best, (mesh.positions.row(n).head<2>().transpose() - p).norm());
  return best;
}

}  // namespace drape::test
