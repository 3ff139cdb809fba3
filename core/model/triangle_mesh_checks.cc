// Checking a triangle mesh read from a file before it becomes an obstacle:
// the sign of a distance is only meaningful on a closed, manifold,
// consistently oriented surface with no degenerate triangle, so anything
// else is refused with the place to mend it.
#include "core/model/triangle_mesh_raw.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace drape {
namespace triangle_mesh {
namespace {

using Eigen::Vector3d;

std::string Format(const Vector3d& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return text;
}

std::string TriangleName(const RawMesh& mesh, int t) {
  std::string name = "triangle " + std::to_string(t + 1);
  if (mesh.triangle_line[t] > 0) name += " (line " + std::to_string(mesh.triangle_line[t]) + ")";
  return name;
}

std::string EdgeName(const RawMesh& mesh, int a, int b) {
  return "the edge between vertex " + std::to_string(mesh.vertex_label[a]) + " " +
         Format(mesh.vertices[a]) + " and vertex " + std::to_string(mesh.vertex_label[b]) + " " +
         Format(mesh.vertices[b]);
}

// Relative to the longest edge, so the test does not depend on units; a
// triangle this thin has no meaningful normal.
void CheckNoDegenerateTriangle(const RawMesh& mesh, const Reporter& report) {
  std::size_t degenerate = 0;
  int first_degenerate = -1;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& [a, b, c] = mesh.triangles[t];
    const Vector3d& pa = mesh.vertices[a];
    const Vector3d &pb = mesh.vertices[b], &pc = mesh.vertices[c];
    const double longest =
        std::max({(pb - pa).squaredNorm(), (pc - pb).squaredNorm(), (pa - pc).squaredNorm()});
    if ((pb - pa).cross(pc - pa).norm() <= 1e-12 * longest) {
      if (degenerate++ == 0) first_degenerate = t;
    }
  }
  if (degenerate > 0)
    report.Fail("has " + Plural(degenerate, "degenerate triangle", "degenerate triangles") +
                " (zero area), e.g. " + TriangleName(mesh, first_degenerate));
}

// Every triangle's three half-edges, sorted by undirected edge.
std::vector<HalfEdge> SortedHalfEdges(const RawMesh& mesh) {
  const int n = static_cast<int>(mesh.triangles.size());
  std::vector<HalfEdge> edges;
  edges.reserve(3 * static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const int from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
      edges.push_back({std::min(from, to), std::max(from, to), t, k, from < to});
    }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.triangle < y.triangle;
  });
  return edges;
}

// Every edge shared by exactly two triangles that traverse it in opposite
// directions: a closed, manifold, consistently oriented surface.
void CheckEdges(const RawMesh& mesh, const std::vector<HalfEdge>& edges, const Reporter& report) {
  std::size_t open = 0, non_manifold = 0, misoriented = 0;
  const HalfEdge *first_open = nullptr, *first_non_manifold = nullptr, *first_misoriented = nullptr;
  std::size_t most_shared = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::size_t shared = j - i;
    if (shared == 1) {
      if (open++ == 0) first_open = &edges[i];
    } else if (shared > 2) {
      if (non_manifold++ == 0) first_non_manifold = &edges[i];
      most_shared = std::max(most_shared, shared);
    } else if (edges[i].forward == edges[i + 1].forward) {
      if (misoriented++ == 0) first_misoriented = &edges[i];
    }
    i = j;
  }
  // Before open edges: a fin or a book of pages leaves open edges too, but
  // the shared edge is what the user has to find.
  if (non_manifold > 0)
    report.Fail("has " + Plural(non_manifold, "non-manifold edge", "non-manifold edges") +
                " (shared by more than two triangles, up to " + std::to_string(most_shared) +
                "), e.g. " + EdgeName(mesh, first_non_manifold->lo, first_non_manifold->hi));
  if (open > 0)
    report.Fail("is not closed: " + Plural(open, "edge belongs", "edges belong") +
                " to only one triangle, e.g. " + EdgeName(mesh, first_open->lo, first_open->hi) +
                " of " + TriangleName(mesh, first_open->triangle));
  if (misoriented > 0)
    report.Fail(
        "has inconsistently oriented faces: " + Plural(misoriented, "edge is", "edges are") +
        " traversed in the same direction by both its triangles, e.g. " +
        EdgeName(mesh, first_misoriented->lo, first_misoriented->hi) + " in " +
        TriangleName(mesh, first_misoriented[0].triangle) + " and " +
        TriangleName(mesh, first_misoriented[1].triangle));
}

// Turns an inward-facing surface outward (as good, once turned), and the
// half-edges with it; a surface that encloses no volume is refused.
void OrientOutward(RawMesh& mesh, std::vector<HalfEdge>& edges, const Reporter& report) {
  // About a point near the mesh, so the volume does not cancel from far away.
  const Vector3d origin = mesh.vertices[mesh.triangles[0][0]];
  double volume6 = 0.0;
  Eigen::AlignedBox3d box;
  for (const auto& [a, b, c] : mesh.triangles) {
    const Vector3d pa = mesh.vertices[a] - origin;
    volume6 += pa.dot((mesh.vertices[b] - origin).cross(mesh.vertices[c] - origin));
    box.extend(mesh.vertices[a]);
  }
  const double size = box.diagonal().norm();
  if (std::abs(volume6) <= 6e-12 * size * size * size) report.Fail("encloses no volume");
  if (volume6 < 0.0) {
    for (auto& triangle : mesh.triangles) std::swap(triangle[1], triangle[2]);
    for (HalfEdge& e : edges) {
      e.forward = !e.forward;
      // Local edge k = (k, k+1) becomes, after swapping corners 1 and 2: 0 → 2, 1 → 1, 2 → 0.
      e.local = 2 - e.local;
    }
  }
}

}  // namespace

// Checks the mesh is a closed, consistently oriented, non-degenerate surface
// and turns it outward. Returns the half-edges sorted by undirected edge, in
// pairs, for the edge pseudo-normals.
std::vector<HalfEdge> CheckAndOrient(RawMesh& mesh, const Reporter& report) {
  if (mesh.triangles.empty()) report.Fail("contains no triangles");
  CheckNoDegenerateTriangle(mesh, report);
  std::vector<HalfEdge> edges = SortedHalfEdges(mesh);
  CheckEdges(mesh, edges, report);
  OrientOutward(mesh, edges, report);
  return edges;
}

}  // namespace triangle_mesh
}  // namespace drape
