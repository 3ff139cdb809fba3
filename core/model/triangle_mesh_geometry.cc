// The distance to a checked triangle mesh: the closest triangle found
// through a bounding-volume tree, signed by pseudo-normals; reading and
// checking the file are in triangle_mesh_reader.cc and triangle_mesh_checks.cc.
#include "core/model/triangle_mesh_geometry.h"

#include "core/geometry/primitive_distance.h"
#include "core/model/triangle_mesh_raw.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace drape {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using triangle_mesh::CheckAndOrient;
using triangle_mesh::HalfEdge;
using triangle_mesh::RawMesh;
using triangle_mesh::ReadMesh;
using triangle_mesh::Reporter;

using Feature = TriangleRegion;

struct ClosestPoint {
  Vector3d point;
  Feature feature;
};

ClosestPoint ClosestOnTriangle(const Vector3d& p,
                               const Vector3d& a,
                               const Vector3d& b,
                               const Vector3d& c) {
  const PointTriangleDistance d = PointTriangle(p, a, b, c);
  return {d.barycentric(0) * a + d.barycentric(1) * b + d.barycentric(2) * c, d.region};
}

class TriangleMeshGeometry final : public ObstacleGeometry {
 public:
  TriangleMeshGeometry(const RawMesh& mesh, const std::vector<HalfEdge>& edges);
  DistanceQuery Query(const Vector3d& x) const override;
  std::optional<Eigen::AlignedBox3d> Bounds() const override { return box_; }

 private:
  // A node's children are the next node and node `right`; a leaf holds
  // triangles [first, first + count) in tree order.
  struct Node {
    Vector3d lo = Vector3d::Zero(), hi = Vector3d::Zero();
    int first_or_right = 0;
    int count = 0;  // 0: an inner node
  };
  struct Triangle {
    Vector3d corner[3];
  };
  struct Hit {
    double distance2 = std::numeric_limits<double>::infinity();
    int triangle = -1;
    ClosestPoint closest{Vector3d::Zero(), Feature::kFace};
  };

  int Build(std::vector<int>& order,
            int begin,
            int end,
            const std::vector<Eigen::AlignedBox3d>& bounds);
  Hit Closest(const Vector3d& x) const;

  static double BoxDistance2(const Node& node, const Vector3d& x) {
    return (node.lo - x).cwiseMax(x - node.hi).cwiseMax(0.0).squaredNorm();
  }

  std::vector<Node> nodes_;
  // Per triangle, in tree order: corners, unit normal, the pseudo-normals
  // of its edges (the sum of both faces' normals) and its corners' vertices.
  std::vector<Triangle> triangles_;
  std::vector<Vector3d> face_normal_;
  std::vector<std::array<Vector3d, 3>> edge_normal_;
  std::vector<std::array<int, 3>> corner_vertex_;
  std::vector<Vector3d> vertex_normal_;  // angle-weighted, per vertex
  double tiny_;                          // below this distance the direction x − c is noise
  Eigen::AlignedBox3d box_;
};

TriangleMeshGeometry::TriangleMeshGeometry(const RawMesh& mesh,
                                           const std::vector<HalfEdge>& edges) {
  const int n = static_cast<int>(mesh.triangles.size());
  std::vector<Vector3d> normal(n);
  std::vector<Eigen::AlignedBox3d> bounds(n);
  vertex_normal_.assign(mesh.vertices.size(), Vector3d::Zero());
  Eigen::AlignedBox3d box;
  for (int t = 0; t < n; ++t) {
    const auto& v = mesh.triangles[t];
    const Vector3d p[3] = {mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]]};
    normal[t] = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    for (int k = 0; k < 3; ++k) {
      const Vector3d u = p[(k + 1) % 3] - p[k], w = p[(k + 2) % 3] - p[k];
      vertex_normal_[v[k]] += std::atan2(u.cross(w).norm(), u.dot(w)) * normal[t];
      bounds[t].extend(p[k]);
    }
    box.extend(bounds[t]);
  }
  tiny_ = 1e-12 * box.diagonal().norm();
  box_ = box;

  std::vector<std::array<Vector3d, 3>> edge_normal(n);
  for (std::size_t i = 0; i + 1 < edges.size(); i += 2) {  // checked: exactly pairs
    const HalfEdge &e = edges[i], &f = edges[i + 1];
    const Vector3d sum = normal[e.triangle] + normal[f.triangle];
    edge_normal[e.triangle][e.local] = sum;
    edge_normal[f.triangle][f.local] = sum;
  }

  std::vector<int> order(n);
  for (int t = 0; t < n; ++t) order[t] = t;
  Build(order, 0, n, bounds);

  triangles_.resize(n);
  face_normal_.resize(n);
  edge_normal_.resize(n);
  corner_vertex_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int t = order[i];
    for (int k = 0; k < 3; ++k) triangles_[i].corner[k] = mesh.vertices[mesh.triangles[t][k]];
    face_normal_[i] = normal[t];
    edge_normal_[i] = edge_normal[t];
    corner_vertex_[i] = mesh.triangles[t];
  }
}

// Median split along the longest extent of the triangles' box centres:
// balanced, so the depth stays near log2(n) and the query's stack small.
int TriangleMeshGeometry::Build(std::vector<int>& order,
                                int begin,
                                int end,
                                const std::vector<Eigen::AlignedBox3d>& bounds) {
  constexpr int kLeafSize = 4;
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Eigen::AlignedBox3d box, centres;
  for (int i = begin; i < end; ++i) {
    box.extend(bounds[order[i]]);
    centres.extend(bounds[order[i]].center());
  }
  nodes_[index].lo = box.min();
  nodes_[index].hi = box.max();
  if (end - begin <= kLeafSize) {
    nodes_[index].first_or_right = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis;
  centres.diagonal().maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(
      order.begin() + begin, order.begin() + middle, order.begin() + end, [&](int x, int y) {
        return bounds[x].min()[axis] + bounds[x].max()[axis] <
               bounds[y].min()[axis] + bounds[y].max()[axis];
      });
  Build(order, begin, middle, bounds);
  const int right = Build(order, middle, end, bounds);
  nodes_[index].first_or_right = right;
  nodes_[index].count = 0;
  return index;
}

TriangleMeshGeometry::Hit TriangleMeshGeometry::Closest(const Vector3d& x) const {
  Hit hit;
  struct Entry {
    int node;
    double distance2;
  };
  Entry stack[64];
  int size = 0;
  stack[size++] = {0, BoxDistance2(nodes_[0], x)};
  while (size > 0) {
    const Entry entry = stack[--size];
    if (entry.distance2 >= hit.distance2) continue;
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (int i = node.first_or_right; i < node.first_or_right + node.count; ++i) {
        const Triangle& t = triangles_[i];
        const ClosestPoint c = ClosestOnTriangle(x, t.corner[0], t.corner[1], t.corner[2]);
        const double distance2 = (x - c.point).squaredNorm();
        if (distance2 < hit.distance2) hit = {distance2, i, c};
      }
      continue;
    }
    const int left = entry.node + 1, right = node.first_or_right;
    const double left2 = BoxDistance2(nodes_[left], x), right2 = BoxDistance2(nodes_[right], x);
    // The nearer child on top, so it is searched first and prunes the other.
    if (left2 < right2) {
      if (right2 < hit.distance2) stack[size++] = {right, right2};
      stack[size++] = {left, left2};
    } else {
      if (left2 < hit.distance2) stack[size++] = {left, left2};
      stack[size++] = {right, right2};
    }
  }
  return hit;
}

DistanceQuery TriangleMeshGeometry::Query(const Vector3d& x) const {
  const Hit hit = Closest(x);
  const int t = hit.triangle;
  const Vector3d& face_normal = face_normal_[t];
  const Vector3d offset = x - hit.closest.point;
  const double r = offset.norm();

  const int feature = static_cast<int>(hit.closest.feature);
  const bool on_edge = feature >= 1 && feature <= 3;
  const bool on_vertex = feature >= 4;
  const Vector3d& pseudo_normal = on_edge     ? edge_normal_[t][feature - 1]
                                  : on_vertex ? vertex_normal_[corner_vertex_[t][feature - 4]]
                                              : face_normal;
  const double sign = offset.dot(pseudo_normal) >= 0.0 ? 1.0 : -1.0;
  const double d = sign * r;
  if (r <= tiny_) return {d, pseudo_normal.normalized(), Matrix3d::Zero()};

  const Vector3d n = offset * (sign / r);
  // An edge or vertex hit with x − c along this face's normal lies on the
  // border of the face's region; taking the face there gives the right
  // (zero) curvature over flat edges and vertices, such as a cap's centre.
  if ((!on_edge && !on_vertex) || std::abs(offset.dot(face_normal)) >= (1.0 - 1e-14) * r)
    return {d, n.dot(face_normal) >= 0.0 ? face_normal : Vector3d(-face_normal), Matrix3d::Zero()};

  Matrix3d h = Matrix3d::Identity() - n * n.transpose();
  if (on_edge) {
    const int k = feature - 1;
    const Vector3d tangent =
        (triangles_[t].corner[(k + 1) % 3] - triangles_[t].corner[k]).normalized();
    h -= tangent * tangent.transpose();
  }
  return {d, n, h / d};
}

}  // namespace

std::unique_ptr<ObstacleGeometry> MakeTriangleMeshGeometry(const std::filesystem::path& file,
                                                           const std::string& where,
                                                           const Eigen::Affine3d& placement) {
  const Reporter report(file, where);
  RawMesh mesh = ReadMesh(file, report);
  // Placed before the checks: a scaling small enough to make a triangle
  // degenerate is reported as such.
  for (Vector3d& v : mesh.vertices) v = placement * v;
  const std::vector<HalfEdge> edges = CheckAndOrient(mesh, report);
  return std::make_unique<TriangleMeshGeometry>(mesh, edges);
}

}  // namespace drape
