#include "core/solve/self_proximity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "core/mechanics/primitive_distance.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;

// A uniform grid of cubes of side `cell`, hashed: each primitive is listed in
// every cell its bounding box (grown by the reach) overlaps.
class SpatialHash {
 public:
  explicit SpatialHash(double cell) : inverse_(1 / cell) {}

  void Insert(int id, const V3& lo, const V3& hi) {
    ForCells(lo, hi, [&](std::int64_t key) { cells_[key].push_back(id); });
  }

  // Each id listed in a cell that [lo, hi] overlaps, once.
  template <typename Visit>
  void Query(const V3& lo, const V3& hi, std::vector<int>& stamp, int query, Visit visit) const {
    ForCells(lo, hi, [&](std::int64_t key) {
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (int id : it->second)
        if (stamp[id] != query) {
          stamp[id] = query;
          visit(id);
        }
    });
  }

 private:
  template <typename F>
  void ForCells(const V3& lo, const V3& hi, F f) const {
    const Eigen::Vector3i a = (lo * inverse_).array().floor().cast<int>();
    const Eigen::Vector3i b = (hi * inverse_).array().floor().cast<int>();
    for (int i = a.x(); i <= b.x(); ++i)
      for (int j = a.y(); j <= b.y(); ++j)
        for (int k = a.z(); k <= b.z(); ++k)
          f((std::int64_t(i) * 73856093) ^ (std::int64_t(j) * 19349663) ^
            (std::int64_t(k) * 83492791));
  }

  double inverse_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

template <size_t N>
std::pair<V3, V3> Box(const std::array<int, N>& nodes, const Positions& x, double grow) {
  V3 lo = x.row(nodes[0]).transpose(), hi = lo;
  for (size_t k = 1; k < N; ++k) {
    lo = lo.cwiseMin(x.row(nodes[k]).transpose());
    hi = hi.cwiseMax(x.row(nodes[k]).transpose());
  }
  return {lo.array() - grow, hi.array() + grow};
}

V3 Row(const Positions& x, int i) {
  return x.row(i).transpose();
}

}  // namespace

SelfProximity::SelfProximity(const Mesh& mesh, double exclusion)
    : rest_(mesh.positions), exclusion_(exclusion) {
  std::vector<std::pair<int, int>> edges;
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    const auto q = mesh.quads.row(e);
    triangles_.push_back({q(0), q(1), q(2)});
    triangles_.push_back({q(0), q(2), q(3)});
    for (const auto& [a, b] : {std::pair{q(0), q(1)},
                               std::pair{q(1), q(2)},
                               std::pair{q(2), q(3)},
                               std::pair{q(3), q(0)},
                               std::pair{q(0), q(2)}})
      edges.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) edges_.push_back({a, b});
}

bool SelfProximity::PointTriangleCounts(int node,
                                        int triangle,
                                        const Positions& x,
                                        double reach) const {
  const auto& t = triangles_[triangle];
  if (node == t[0] || node == t[1] || node == t[2]) return false;
  if (PointTriangle(Row(x, node), Row(x, t[0]), Row(x, t[1]), Row(x, t[2])).squared > reach * reach)
    return false;
  return PointTriangle(Row(rest_, node), Row(rest_, t[0]), Row(rest_, t[1]), Row(rest_, t[2]))
             .squared > exclusion_ * exclusion_;
}

bool SelfProximity::EdgeEdgeCounts(int a, int b, const Positions& x, double reach) const {
  const auto& p = edges_[a];
  const auto& q = edges_[b];
  if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) return false;
  if (EdgeEdge(Row(x, p[0]), Row(x, p[1]), Row(x, q[0]), Row(x, q[1])).squared > reach * reach)
    return false;
  return EdgeEdge(Row(rest_, p[0]), Row(rest_, p[1]), Row(rest_, q[0]), Row(rest_, q[1])).squared >
         exclusion_ * exclusion_;
}

ProximityPairs SelfProximity::Candidates(const Positions& x, double reach) const {
  ProximityPairs out;
  if (x.rows() == 0) return out;
  // Cells no smaller than the mean edge, so that a primitive spans few.
  double mean_edge = 0;
  for (const auto& e : edges_) mean_edge += (x.row(e[0]) - x.row(e[1])).norm();
  mean_edge /= std::max<size_t>(1, edges_.size());
  const double cell = std::max({reach, mean_edge, 1e-12});

  SpatialHash triangles(cell);
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const auto [lo, hi] = Box(triangles_[t], x, reach);
    triangles.Insert(static_cast<int>(t), lo, hi);
  }
  std::vector<int> stamp(triangles_.size(), -1);
  for (int i = 0; i < x.rows(); ++i) {
    const V3 p = Row(x, i);
    triangles.Query(p, p, stamp, i, [&](int t) {
      if (PointTriangleCounts(i, t, x, reach)) out.point_triangle.push_back({i, t});
    });
  }

  SpatialHash edges(cell);
  for (size_t e = 0; e < edges_.size(); ++e) {
    const auto [lo, hi] = Box(edges_[e], x, reach);
    edges.Insert(static_cast<int>(e), lo, hi);
  }
  stamp.assign(edges_.size(), -1);
  for (size_t e = 0; e < edges_.size(); ++e) {
    const auto [lo, hi] = Box(edges_[e], x, 0.0);
    edges.Query(lo, hi, stamp, static_cast<int>(e), [&](int f) {
      if (f > static_cast<int>(e) && EdgeEdgeCounts(static_cast<int>(e), f, x, reach))
        out.edge_edge.push_back({static_cast<int>(e), f});
    });
  }
  std::sort(out.point_triangle.begin(), out.point_triangle.end());
  std::sort(out.edge_edge.begin(), out.edge_edge.end());
  return out;
}

ProximityPairs SelfProximity::CandidatesByBruteForce(const Positions& x, double reach) const {
  ProximityPairs out;
  for (int i = 0; i < x.rows(); ++i)
    for (size_t t = 0; t < triangles_.size(); ++t)
      if (PointTriangleCounts(i, static_cast<int>(t), x, reach))
        out.point_triangle.push_back({i, static_cast<int>(t)});
  for (size_t e = 0; e < edges_.size(); ++e)
    for (size_t f = e + 1; f < edges_.size(); ++f)
      if (EdgeEdgeCounts(static_cast<int>(e), static_cast<int>(f), x, reach))
        out.edge_edge.push_back({static_cast<int>(e), static_cast<int>(f)});
  return out;
}

double SelfProximity::SmallestDistance(const Positions& x, double reach) const {
  const ProximityPairs pairs = Candidates(x, reach);
  double smallest = INFINITY;
  for (const auto& [i, t] : pairs.point_triangle) {
    const auto& tri = triangles_[t];
    smallest = std::min(
        smallest, PointTriangle(Row(x, i), Row(x, tri[0]), Row(x, tri[1]), Row(x, tri[2])).squared);
  }
  for (const auto& [a, b] : pairs.edge_edge) {
    const auto& p = edges_[a];
    const auto& q = edges_[b];
    smallest = std::min(smallest,
                        EdgeEdge(Row(x, p[0]), Row(x, p[1]), Row(x, q[0]), Row(x, q[1])).squared);
  }
  return std::sqrt(smallest);
}

}  // namespace drape
