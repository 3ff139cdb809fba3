#include "core/model/planar_graph.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "core/model/mesh.h"
#include "core/model/polygon_checks.h"

namespace drape {
namespace {

std::string PointText(const Eigen::Vector2d& p) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g) m", p.x(), p.y());
  return buffer;
}

double DistanceToSegment(const Eigen::Vector2d& p,
                         const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b,
                         Eigen::Vector2d* nearest = nullptr) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  const Eigen::Vector2d q = a + t * ab;
  if (nearest) *nearest = q;
  return (p - q).norm();
}

class GraphBuilder {
 public:
  GraphBuilder(const std::vector<Eigen::Vector2d>& outline,
               const std::vector<std::vector<Eigen::Vector2d>>& holes,
               double snap)
      : snap_(snap) {
    Eigen::Vector2d lo = outline[0], hi = outline[0];
    for (const auto& v : outline) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    merge_ = 1e-9 * (hi - lo).norm();
    zero_ = 1e-12 * (hi - lo).squaredNorm();
    AddLoop(outline);
    for (const auto& hole : holes) AddLoop(hole);
  }

  void AddLine(const FeatureLine& line) {
    std::vector<int> ids;
    for (const auto& p : line.points) {
      const int id = Attach(p);
      if (id < 0)
        throw MeshError("MeshPolygon: " + line.name + " leaves the part at " + PointText(p));
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) AddSegment(ids[i], ids[i + 1], line.name);
  }

  void AddPoint(const FeaturePoint& point) {
    const int id = Attach(point.at);
    if (id < 0)
      throw MeshError("MeshPolygon: " + point.name + " lies outside the part at " +
                      PointText(point.at));
    embedded_points_.push_back(id);
  }

  PlanarGraph Finish() && {
    PlanarGraph graph;
    std::vector<char> on_curve(vertices_.size(), 0);
    for (const auto& loop : loops_)
      for (int v : loop) on_curve[v] = 1;
    for (const auto& s : segments_) on_curve[s[0]] = on_curve[s[1]] = 1;
    for (int v : embedded_points_)
      if (!on_curve[v]) {
        graph.points.push_back(v);
        on_curve[v] = 1;
      }
    graph.vertices = std::move(vertices_);
    graph.loops = std::move(loops_);
    graph.segments = std::move(segments_);
    return graph;
  }

 private:
  void AddLoop(const std::vector<Eigen::Vector2d>& polygon) {
    std::vector<int> loop;
    for (const auto& v : polygon) {
      loop.push_back(static_cast<int>(vertices_.size()));
      vertices_.push_back(v);
    }
    loops_.push_back(std::move(loop));
  }

  int NewVertex(const Eigen::Vector2d& p) {
    vertices_.push_back(p);
    return static_cast<int>(vertices_.size()) - 1;
  }

  bool Inside(const Eigen::Vector2d& p) const {
    if (!InsidePolygon(Polygon(0), p)) return false;
    for (std::size_t h = 1; h < loops_.size(); ++h)
      if (InsidePolygon(Polygon(h), p)) return false;
    return true;
  }

  std::vector<Eigen::Vector2d> Polygon(std::size_t loop) const {
    std::vector<Eigen::Vector2d> points;
    for (int v : loops_[loop]) points.push_back(vertices_[v]);
    return points;
  }

  double DistanceToLoops(const Eigen::Vector2d& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& loop : loops_)
      for (std::size_t i = 0; i < loop.size(); ++i)
        best = std::min(
            best, DistanceToSegment(p, vertices_[loop[i]], vertices_[loop[(i + 1) % loop.size()]]));
    return best;
  }

  // The vertex p becomes: an existing one within `snap`, else a new one on
  // the nearest loop edge or segment within `snap`, else a free one inside;
  // −1 outside the part.
  int Attach(const Eigen::Vector2d& p) {
    int nearest = -1;
    double nearest_d = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < vertices_.size(); ++v)
      if (const double d = (vertices_[v] - p).norm(); d < nearest_d) {
        nearest_d = d;
        nearest = static_cast<int>(v);
      }
    if (nearest_d <= snap_) return nearest;

    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector2d foot = p;
    // The nearest: loop l's edge i (segment < 0), or segment `segment`.
    std::size_t l_best = 0, i_best = 0;
    std::ptrdiff_t segment = -1;
    for (std::size_t l = 0; l < loops_.size(); ++l)
      for (std::size_t i = 0; i < loops_[l].size(); ++i) {
        Eigen::Vector2d q;
        const double d = DistanceToSegment(
            p, vertices_[loops_[l][i]], vertices_[loops_[l][(i + 1) % loops_[l].size()]], &q);
        if (d < best) {
          best = d;
          foot = q;
          l_best = l;
          i_best = i;
        }
      }
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      Eigen::Vector2d q;
      const double d =
          DistanceToSegment(p, vertices_[segments_[s][0]], vertices_[segments_[s][1]], &q);
      if (d < best) {
        best = d;
        foot = q;
        segment = static_cast<std::ptrdiff_t>(s);
      }
    }
    if (best <= snap_) {
      const int v = NewVertex(foot);
      if (segment < 0) {
        auto& loop = loops_[l_best];
        loop.insert(loop.begin() + static_cast<std::ptrdiff_t>(i_best) + 1, v);
      } else {
        SplitSegment(static_cast<std::size_t>(segment), v);
      }
      return v;
    }
    return Inside(p) ? NewVertex(p) : -1;
  }

  void SplitSegment(std::size_t s, int v) {
    const int end = segments_[s][1];
    segments_[s][1] = v;
    segments_.push_back({v, end});
    segment_names_.push_back(segment_names_[s]);
  }

  // Where segments ab and cd cross (they touch and are not parallel).
  std::optional<Eigen::Vector2d> Crossing(const Eigen::Vector2d& a,
                                          const Eigen::Vector2d& b,
                                          const Eigen::Vector2d& c,
                                          const Eigen::Vector2d& d) const {
    const double denominator = Cross(b - a, d - c);
    if (std::abs(denominator) <= zero_) return std::nullopt;
    const double t = std::clamp(Cross(c - a, d - c) / denominator, 0.0, 1.0);
    return a + t * (b - a);
  }

  // Whether segments ab and cd, which share an end, lie along each other.
  bool Overlap(int a, int b, int c, int d) const {
    const int shared = (a == c || a == d) ? a : b;
    const int from_ab = shared == a ? b : a;
    const int from_cd = shared == c ? d : c;
    const Eigen::Vector2d u = vertices_[from_ab] - vertices_[shared];
    const Eigen::Vector2d w = vertices_[from_cd] - vertices_[shared];
    return std::abs(Cross(u, w)) <= zero_ && u.dot(w) > 0;
  }

  void AddSegment(int a, int b, const std::string& name) {
    const Eigen::Vector2d& pa = vertices_[a];
    const Eigen::Vector2d& pb = vertices_[b];
    const Eigen::Vector2d middle = 0.5 * (pa + pb);
    // Along the boundary: already a curve of the mesh.
    if (DistanceToLoops(middle) <= merge_) return;
    if (!Inside(middle))
      throw MeshError("MeshPolygon: " + name + " leaves the part near " + PointText(middle));
    for (std::size_t l = 0; l < loops_.size(); ++l) {
      const auto& loop = loops_[l];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int u = loop[i], w = loop[(i + 1) % loop.size()];
        if (u == a || u == b || w == a || w == b) continue;
        if (SegmentsTouch(pa, pb, vertices_[u], vertices_[w], zero_))
          throw MeshError("MeshPolygon: " + name + " crosses " +
                          (l == 0 ? std::string("the outline") : "hole " + std::to_string(l - 1)) +
                          " near " + PointText(vertices_[u]) +
                          "; an internal line may end on the boundary, not cross it");
      }
    }
    for (std::size_t s = 0; s < segments_.size(); ++s) {
      const int c = segments_[s][0], d = segments_[s][1];
      if (c == a || c == b || d == a || d == b) {
        if (!(c == a && d == b) && !(c == b && d == a) && !Overlap(a, b, c, d)) continue;
        throw MeshError("MeshPolygon: " + name + " runs along " + segment_names_[s] + " near " +
                        PointText(middle) + "; draw shared stretches once");
      }
      if (!SegmentsTouch(pa, pb, vertices_[c], vertices_[d], zero_)) continue;
      const auto x = Crossing(pa, pb, vertices_[c], vertices_[d]);
      if (!x)
        throw MeshError("MeshPolygon: " + name + " runs along " + segment_names_[s] + " near " +
                        PointText(middle) + "; draw shared stretches once");
      // Split both at the crossing (an end of either when it lies there),
      // then add the two halves of ab, which may cross others.
      int v = -1;
      for (int end : {a, b, c, d})
        if ((vertices_[end] - *x).norm() <= merge_) v = end;
      if (v < 0) v = NewVertex(*x);
      if (v != c && v != d) SplitSegment(s, v);
      if (v == a || v == b) continue;
      AddSegment(a, v, name);
      AddSegment(v, b, name);
      return;
    }
    segments_.push_back({a, b});
    segment_names_.push_back(name);
  }

  double snap_;
  double merge_ = 0;
  double zero_ = 0;
  std::vector<Eigen::Vector2d> vertices_;
  std::vector<std::vector<int>> loops_;
  std::vector<std::array<int, 2>> segments_;
  std::vector<std::string> segment_names_;
  std::vector<int> embedded_points_;
};

}  // namespace

PlanarGraph BuildPlanarGraph(const std::vector<Eigen::Vector2d>& outline,
                             const MeshFeatures& features,
                             double snap) {
  GraphBuilder builder(outline, features.holes, snap);
  for (const auto& line : features.lines) builder.AddLine(line);
  for (const auto& point : features.points) builder.AddPoint(point);
  return std::move(builder).Finish();
}

}  // namespace drape
