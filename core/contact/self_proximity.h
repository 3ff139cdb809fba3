// Which of the fabric's own surface primitives can touch each other (the
// broad phase of self-contact, issue 17). The mid-surface is taken as
// triangles (each quad split along its diagonal 0–2), their edges, and the
// nodes. A point–triangle or edge–edge pair counts when its primitives lie
// more than `exclusion` apart in the rest shape (neighbours in the fabric
// never touch), or on separate pieces of the mesh (stacked sheets) and within `reach` of each other
// in the current state. Pairs are found through a spatial grid of the primitives' bounding boxes.
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

// A bound on how much a motion (one row per node) can change the distance
// between any two points of the fabric, halved: max_i |d_i − c| with c the
// middle of the motions' range. A rigid translation changes no distance
// and gives 0. [m]
double MotionSpread(const Positions& motion);

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

  // Every pair whose boxes swept from `positions` to `positions + motion`
  // come within `gap` [m] of each other and whose motion relative to each
  // other could close their present gap to `gap`: all that can come within
  // `gap` during that motion (the broad phase of the step filter).
  ProximityPairs SweptCandidates(const Positions& positions,
                                 const Positions& motion,
                                 double gap) const;

  // The same pairs by testing every one: for tests of the grid.
  ProximityPairs CandidatesByBruteForce(const Positions& positions, double reach) const;
  ProximityPairs SweptCandidatesByBruteForce(const Positions& positions,
                                             const Positions& motion,
                                             double gap) const;

  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }

 private:
  bool PointTriangleCounts(int node, int triangle, const Positions& x, double reach) const;
  bool EdgeEdgeCounts(int a, int b, const Positions& x, double reach) const;
  bool SweptPointTriangleCounts(
      int node, int triangle, const Positions& x, const Positions& motion, double gap) const;
  bool SweptEdgeEdgeCounts(
      int a, int b, const Positions& x, const Positions& motion, double gap) const;
  bool PointTriangleApartAtRest(int node, int triangle) const;
  bool EdgeEdgeApartAtRest(int a, int b) const;

  Positions rest_;
  std::vector<int> piece_;  // per node, its connected piece of the mesh
  double exclusion_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 2>> edges_;
  // Rest-shape boxes: primitives whose boxes are farther apart than the
  // exclusion count without the exact test.
  std::vector<Eigen::Array3d> rest_triangle_lo_, rest_triangle_hi_;
  std::vector<Eigen::Array3d> rest_edge_lo_, rest_edge_hi_;
};

}  // namespace drape
