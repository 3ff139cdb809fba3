// Which of the fabric's own surface primitives can touch each other (the
// broad phase of self-contact, issue 17). The mid-surface is taken as
// triangles (each quad split along its diagonal 0–2), their edges, and the
// nodes. A point–triangle or edge–edge pair counts when its primitives lie
// more than `exclusion` apart in the rest shape (neighbours in the fabric
// never touch) and within `reach` of each other in the current state. Pairs
// are found through a spatial hash of the state's positions.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

#include "core/model/mesh.h"

namespace drape {

using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3>;

struct ProximityPairs {
  std::vector<std::array<int, 2>> point_triangle;  // node, triangle
  std::vector<std::array<int, 2>> edge_edge;       // edge, edge (first < second)
};

class SelfProximity {
 public:
  // `exclusion` [m]: pairs closer than this in the rest shape never count.
  SelfProximity(const Mesh& mesh, double exclusion);

  // Every pair within `reach` [m] in `positions` (one row per node).
  ProximityPairs Candidates(const Positions& positions, double reach) const;

  // The smallest distance between the mid-surfaces of parts more than
  // `exclusion` apart in the rest shape, among pairs within `reach` [m];
  // +∞ when no pair is that close.
  double SmallestDistance(const Positions& positions, double reach) const;

  // The same pairs by testing every one: for tests of the hash.
  ProximityPairs CandidatesByBruteForce(const Positions& positions, double reach) const;

  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }

 private:
  bool PointTriangleCounts(int node, int triangle, const Positions& x, double reach) const;
  bool EdgeEdgeCounts(int a, int b, const Positions& x, double reach) const;

  Positions rest_;
  double exclusion_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 2>> edges_;
};

}  // namespace drape
