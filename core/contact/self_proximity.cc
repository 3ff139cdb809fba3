#include "core/contact/self_proximity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/geometry/primitive_distance.h"

namespace drape {
namespace {

using V3 = Eigen::Vector3d;
using A3 = Eigen::Array3d;

// Axis-aligned boxes, one per primitive.
struct Boxes {
  std::vector<A3> lo, hi;
  void Add(const A3& l, const A3& h) {
    lo.push_back(l);
    hi.push_back(h);
  }
};

bool Overlap(const A3& alo, const A3& ahi, const A3& blo, const A3& bhi) {
  return (alo <= bhi).all() && (blo <= ahi).all();
}

// The gap between two boxes (0 where they overlap).
double BoxGap(const A3& alo, const A3& ahi, const A3& blo, const A3& bhi) {
  return (blo - ahi).max(alo - bhi).max(0.0).matrix().norm();
}

// The largest distance between a point of one box and a point of the other.
double BoxReach(const A3& alo, const A3& ahi, const A3& blo, const A3& bhi) {
  return (bhi - alo).max(ahi - blo).matrix().norm();
}

// A uniform grid of cubes hashed into a table of buckets (Teschner et al.,
// "Optimized spatial hashing for collision detection of deformable
// objects", VMV 2003): each box is listed in the bucket of every cell it
// overlaps, the buckets filled by counting, without sorting. Cells are as
// large as the mean box, so that a box spans few; cells that share a bucket
// only cost a box test.
class BoxGrid {
 public:
  explicit BoxGrid(const Boxes& listed) : listed_(listed) {
    const size_t n = listed.lo.size();
    double extent = 0;
    for (size_t b = 0; b < n; ++b) extent += (listed.hi[b] - listed.lo[b]).maxCoeff();
    inverse_ = 1 / std::max(extent / std::max<size_t>(1, n), 1e-12);
    size_t buckets = 64;
    while (buckets < 8 * n) buckets *= 2;
    mask_ = buckets - 1;
    start_.assign(buckets + 1, 0);
    for (size_t b = 0; b < n; ++b)
      ForBuckets(listed.lo[b], listed.hi[b], [&](size_t k) { ++start_[k + 1]; });
    for (size_t k = 0; k < buckets; ++k) start_[k + 1] += start_[k];
    ids_.resize(start_.back());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (size_t b = 0; b < n; ++b)
      ForBuckets(listed.lo[b], listed.hi[b], [&](size_t k) { ids_[fill[k]++] = int(b); });
  }

  // Each listed box that overlaps [lo, hi], once per `query` (`stamp`
  // remembers the last query that visited each box).
  template <typename Visit>
  void Query(const A3& lo, const A3& hi, std::vector<int>& stamp, int query, Visit visit) const {
    ForBuckets(lo, hi, [&](size_t k) {
      for (int i = start_[k]; i < start_[k + 1]; ++i) {
        const int id = ids_[i];
        if (stamp[id] == query) continue;
        stamp[id] = query;
        if (Overlap(lo, hi, listed_.lo[id], listed_.hi[id])) visit(id);
      }
    });
  }

 private:
  template <typename F>
  void ForBuckets(const A3& lo, const A3& hi, F f) const {
    if (!lo.allFinite() || !hi.allFinite()) return;
    const Eigen::Array<std::int64_t, 3, 1> a = (lo * inverse_).floor().cast<std::int64_t>();
    const Eigen::Array<std::int64_t, 3, 1> b = (hi * inverse_).floor().cast<std::int64_t>();
    for (std::int64_t i = a.x(); i <= b.x(); ++i)
      for (std::int64_t j = a.y(); j <= b.y(); ++j)
        for (std::int64_t k = a.z(); k <= b.z(); ++k)
          f(static_cast<size_t>((i * 73856093) ^ (j * 19349663) ^ (k * 83492791)) & mask_);
  }

  const Boxes& listed_;
  double inverse_ = 1;
  size_t mask_ = 0;
  std::vector<int> start_;  // bucket k holds ids_[start_[k], start_[k + 1])
  std::vector<int> ids_;
};

// The box of a primitive's nodes in x and in x + motion (when given),
// grown by `grow` on every side.
template <size_t N>
std::pair<A3, A3> Box(const std::array<int, N>& nodes,
                      const Positions& x,
                      const Positions* motion,
                      double grow) {
  A3 lo = x.row(nodes[0]).transpose().array(), hi = lo;
  for (size_t k = 0; k < N; ++k) {
    const A3 p = x.row(nodes[k]).transpose().array();
    lo = lo.min(p);
    hi = hi.max(p);
    if (motion) {
      const A3 q = p + motion->row(nodes[k]).transpose().array();
      lo = lo.min(q);
      hi = hi.max(q);
    }
  }
  return {lo - grow, hi + grow};
}

template <size_t N>
Boxes BoxesOf(const std::vector<std::array<int, N>>& primitives,
              const Positions& x,
              const Positions* motion,
              double grow) {
  Boxes boxes;
  boxes.lo.reserve(primitives.size());
  boxes.hi.reserve(primitives.size());
  for (const auto& p : primitives) {
    const auto [lo, hi] = Box(p, x, motion, grow);
    boxes.Add(lo, hi);
  }
  return boxes;
}

V3 Row(const Positions& x, int i) {
  return x.row(i).transpose();
}

// Point–triangle pairs whose boxes overlap (points' boxes against
// triangles' boxes) and edge–edge pairs (each once), passed to `keep`.
template <typename KeepPointTriangle, typename KeepEdgeEdge>
ProximityPairs OverlappingPairs(const Boxes& points,
                                const Boxes& triangles,
                                const Boxes& edge_queries,
                                const Boxes& edges,
                                KeepPointTriangle keep_point_triangle,
                                KeepEdgeEdge keep_edge_edge) {
  ProximityPairs out;
  {
    const BoxGrid grid(triangles);
    std::vector<int> stamp(triangles.lo.size(), -1);
    for (int i = 0; i < static_cast<int>(points.lo.size()); ++i)
      grid.Query(points.lo[i], points.hi[i], stamp, i, [&](int t) {
        if (keep_point_triangle(i, t)) out.point_triangle.push_back({i, t});
      });
  }
  {
    const BoxGrid grid(edges);
    std::vector<int> stamp(edges.lo.size(), -1);
    for (int e = 0; e < static_cast<int>(edge_queries.lo.size()); ++e)
      grid.Query(edge_queries.lo[e], edge_queries.hi[e], stamp, e, [&](int f) {
        if (f > e && keep_edge_edge(e, f)) out.edge_edge.push_back({e, f});
      });
  }
  std::sort(out.point_triangle.begin(), out.point_triangle.end());
  std::sort(out.edge_edge.begin(), out.edge_edge.end());
  return out;
}

Boxes NodeBoxes(const Positions& x, const Positions* motion) {
  Boxes boxes;
  for (int i = 0; i < x.rows(); ++i) {
    const auto [lo, hi] = Box(std::array<int, 1>{i}, x, motion, 0.0);
    boxes.Add(lo, hi);
  }
  return boxes;
}

// Whether primitives a and b (their nodes) can come within `gap` of each
// other while moving from x to x + motion: seen from a frame moving with
// a's first node, each node moves at most its motion relative to that node,
// and the distance drops by at most the largest such motion on each side.
// Their current boxes' gap bounds the distance from below.
template <size_t N, size_t M>
bool CanComeWithin(const std::array<int, N>& a,
                   const std::array<int, M>& b,
                   const Positions& x,
                   const Positions& motion,
                   double gap) {
  const Eigen::RowVector3d c = motion.row(a[0]);
  double relative = 0;
  for (int k : a) relative = std::max(relative, (motion.row(k) - c).norm());
  double other = 0;
  for (int k : b) other = std::max(other, (motion.row(k) - c).norm());
  const auto [alo, ahi] = Box(a, x, nullptr, 0.0);
  const auto [blo, bhi] = Box(b, x, nullptr, 0.0);
  return BoxGap(alo, ahi, blo, bhi) - relative - other <= gap;
}

}  // namespace

double MotionSpread(const Positions& motion) {
  if (motion.rows() == 0) return 0;
  const Eigen::RowVector3d c = 0.5 * (motion.colwise().maxCoeff() + motion.colwise().minCoeff());
  return (motion.rowwise() - c).rowwise().norm().maxCoeff();
}

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
  // Connected pieces, by union–find over the edges.
  piece_.resize(rest_.rows());
  for (int i = 0; i < static_cast<int>(piece_.size()); ++i) piece_[i] = i;
  auto root = [&](int i) {
    while (piece_[i] != i) i = piece_[i] = piece_[piece_[i]];
    return i;
  };
  for (const auto& e : edges_) piece_[root(e[0])] = root(e[1]);
  for (int i = 0; i < static_cast<int>(piece_.size()); ++i) piece_[i] = root(i);
  for (const auto& t : triangles_) {
    const auto [lo, hi] = Box(t, rest_, nullptr, 0.0);
    rest_triangle_lo_.push_back(lo);
    rest_triangle_hi_.push_back(hi);
  }
  for (const auto& e : edges_) {
    const auto [lo, hi] = Box(e, rest_, nullptr, 0.0);
    rest_edge_lo_.push_back(lo);
    rest_edge_hi_.push_back(hi);
  }
}

bool SelfProximity::PointTriangleApartAtRest(int node, int triangle) const {
  const auto& t = triangles_[triangle];
  if (node == t[0] || node == t[1] || node == t[2]) return false;
  if (piece_[node] != piece_[t[0]]) return true;
  const A3 p = rest_.row(node).transpose().array();
  if (BoxGap(p, p, rest_triangle_lo_[triangle], rest_triangle_hi_[triangle]) > exclusion_)
    return true;
  if (BoxReach(p, p, rest_triangle_lo_[triangle], rest_triangle_hi_[triangle]) <= exclusion_)
    return false;
  return PointTriangle(Row(rest_, node), Row(rest_, t[0]), Row(rest_, t[1]), Row(rest_, t[2]))
             .squared > exclusion_ * exclusion_;
}

bool SelfProximity::EdgeEdgeApartAtRest(int a, int b) const {
  const auto& p = edges_[a];
  const auto& q = edges_[b];
  if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) return false;
  if (piece_[p[0]] != piece_[q[0]]) return true;
  if (BoxGap(rest_edge_lo_[a], rest_edge_hi_[a], rest_edge_lo_[b], rest_edge_hi_[b]) > exclusion_)
    return true;
  if (BoxReach(rest_edge_lo_[a], rest_edge_hi_[a], rest_edge_lo_[b], rest_edge_hi_[b]) <=
      exclusion_)
    return false;
  return EdgeEdge(Row(rest_, p[0]), Row(rest_, p[1]), Row(rest_, q[0]), Row(rest_, q[1])).squared >
         exclusion_ * exclusion_;
}

bool SelfProximity::PointTriangleCounts(int node,
                                        int triangle,
                                        const Positions& x,
                                        double reach) const {
  const auto& t = triangles_[triangle];
  // Apart at rest first: with the rest boxes it is mostly decided without
  // an exact distance, and it rejects the many neighbours around a node.
  return PointTriangleApartAtRest(node, triangle) &&
         PointTriangle(Row(x, node), Row(x, t[0]), Row(x, t[1]), Row(x, t[2])).squared <=
             reach * reach;
}

bool SelfProximity::EdgeEdgeCounts(int a, int b, const Positions& x, double reach) const {
  const auto& p = edges_[a];
  const auto& q = edges_[b];
  return EdgeEdgeApartAtRest(a, b) &&
         EdgeEdge(Row(x, p[0]), Row(x, p[1]), Row(x, q[0]), Row(x, q[1])).squared <= reach * reach;
}

ProximityPairs SelfProximity::Candidates(const Positions& x, double reach) const {
  if (x.rows() == 0) return {};
  return OverlappingPairs(
      NodeBoxes(x, nullptr),
      BoxesOf(triangles_, x, nullptr, reach),
      BoxesOf(edges_, x, nullptr, 0.0),
      BoxesOf(edges_, x, nullptr, reach),
      [&](int i, int t) { return PointTriangleCounts(i, t, x, reach); },
      [&](int e, int f) { return EdgeEdgeCounts(e, f, x, reach); });
}

ProximityPairs SelfProximity::SweptCandidates(const Positions& x,
                                              const Positions& motion,
                                              double gap) const {
  if (x.rows() == 0) return {};
  return OverlappingPairs(
      NodeBoxes(x, &motion),
      BoxesOf(triangles_, x, &motion, gap),
      BoxesOf(edges_, x, &motion, 0.0),
      BoxesOf(edges_, x, &motion, gap),
      [&](int i, int t) { return SweptPointTriangleCounts(i, t, x, motion, gap); },
      [&](int e, int f) { return SweptEdgeEdgeCounts(e, f, x, motion, gap); });
}

bool SelfProximity::SweptPointTriangleCounts(
    int node, int triangle, const Positions& x, const Positions& motion, double gap) const {
  const auto& t = triangles_[triangle];
  if (node == t[0] || node == t[1] || node == t[2]) return false;
  return CanComeWithin(std::array<int, 1>{node}, t, x, motion, gap) &&
         PointTriangleApartAtRest(node, triangle);
}

bool SelfProximity::SweptEdgeEdgeCounts(
    int a, int b, const Positions& x, const Positions& motion, double gap) const {
  const auto& p = edges_[a];
  const auto& q = edges_[b];
  if (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1]) return false;
  return CanComeWithin(p, q, x, motion, gap) && EdgeEdgeApartAtRest(a, b);
}

ProximityPairs SelfProximity::SweptCandidatesByBruteForce(const Positions& x,
                                                          const Positions& motion,
                                                          double gap) const {
  ProximityPairs out;
  for (int i = 0; i < x.rows(); ++i) {
    const auto [plo, phi] = Box(std::array<int, 1>{i}, x, &motion, 0.0);
    for (size_t t = 0; t < triangles_.size(); ++t) {
      const auto [lo, hi] = Box(triangles_[t], x, &motion, gap);
      if (Overlap(plo, phi, lo, hi) &&
          SweptPointTriangleCounts(i, static_cast<int>(t), x, motion, gap))
        out.point_triangle.push_back({i, static_cast<int>(t)});
    }
  }
  for (size_t e = 0; e < edges_.size(); ++e) {
    const auto [elo, ehi] = Box(edges_[e], x, &motion, 0.0);
    for (size_t f = e + 1; f < edges_.size(); ++f) {
      const auto [lo, hi] = Box(edges_[f], x, &motion, gap);
      if (Overlap(elo, ehi, lo, hi) &&
          SweptEdgeEdgeCounts(static_cast<int>(e), static_cast<int>(f), x, motion, gap))
        out.edge_edge.push_back({static_cast<int>(e), static_cast<int>(f)});
    }
  }
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
