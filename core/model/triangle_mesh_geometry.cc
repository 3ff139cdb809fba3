#include "core/model/triangle_mesh_geometry.h"

#include "core/geometry/primitive_distance.h"
#include "core/model/scene_error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace drape {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// ---- reading ----------------------------------------------------------------

// Triangles as read, vertices already merged, with what messages need to
// point the user back into the file.
struct RawMesh {
  std::vector<Vector3d> vertices;
  std::vector<int> vertex_label;  // the vertex's number in messages (1-based)
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_line;  // source line of the face or facet; 0 if none (binary STL)
};

std::string Format(const Vector3d& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
  return text;
}

std::string Plural(std::size_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Every error names the obstacle (`where`) and the file.
class Reporter {
 public:
  Reporter(const std::filesystem::path& file, std::string where)
      : where_(std::move(where)), name_(file.filename().string()) {}

  [[noreturn]] void Fail(const std::string& what) const {
    throw SceneError(where_, "mesh '" + name_ + "': " + what);
  }
  [[noreturn]] void FailAt(int line, const std::string& what) const {
    Fail("line " + std::to_string(line) + ": " + what);
  }

 private:
  std::string where_;
  std::string name_;
};

// Exact-coordinate merge: STL repeats every vertex per facet, and some OBJ
// exporters split vertices along seams; closedness can only be checked on
// shared vertices. -0.0 and 0.0 are the same point.
class VertexMerger {
 public:
  int Add(const Vector3d& p, int label, RawMesh& mesh) {
    const Key key{std::bit_cast<std::uint64_t>(p.x() + 0.0),
                  std::bit_cast<std::uint64_t>(p.y() + 0.0),
                  std::bit_cast<std::uint64_t>(p.z() + 0.0)};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      mesh.vertices.push_back(p);
      mesh.vertex_label.push_back(label);
    }
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h ^= (h >> 29) ^ (k[1] * 0xBF58476D1CE4E5B9ull);
      h ^= (h >> 31) ^ (k[2] * 0x94D049BB133111EBull);
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::unordered_map<Key, int, Hash> index_;
};

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (true) {
    i = line.find_first_not_of(" \t\r\f\v", i);
    if (i == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", i), line.size());
    tokens.push_back(line.substr(i, end - i));
    i = end;
  }
  return tokens;
}

bool ParseDouble(std::string_view text, double& value) {
  // from_chars takes no '+', and a '+' may not be followed by another sign.
  if (text.starts_with('+')) {
    text.remove_prefix(1);
    if (text.starts_with('+') || text.starts_with('-')) return false;
  }
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size() &&
         std::isfinite(value);
}

// Larger coordinates overflow the cross products and volumes (cubes of
// coordinate differences) the checks and queries compute: NaN passed every
// check and the closest-triangle search found none. No obstacle is this
// large in any unit.
constexpr double kMaxCoordinate = 1e50;

// A vertex coordinate; the reason it is not one otherwise.
bool ParseCoordinate(std::string_view text, double& value, std::string& why) {
  if (!ParseDouble(text, value)) {
    why = "bad number '" + std::string(text) + "' in vertex";
    return false;
  }
  if (std::abs(value) > kMaxCoordinate) {
    why = "coordinate '" + std::string(text) + "' is too large (more than 1e50 in magnitude)";
    return false;
  }
  return true;
}

bool ParseInt(std::string_view text, long long& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

std::string Quoted(std::string_view text) {
  std::string quoted(1, '\'');
  quoted.append(text);
  quoted.push_back('\'');
  return quoted;
}

// Calls `line_fn(number, text)` for each line, without its end-of-line.
template <class F>
void ForEachLine(std::string_view text, F&& line_fn) {
  int number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    line_fn(++number, text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
}

RawMesh ReadObj(std::string_view text, const Reporter& report) {
  struct Face {
    std::vector<long long> corners;  // 0-based file vertex indices, not yet range-checked
    int line;
  };
  std::vector<Vector3d> positions;
  std::vector<Face> faces;
  ForEachLine(text, [&](int line, std::string_view content) {
    content = content.substr(0, content.find('#'));
    const std::vector<std::string_view> tokens = Tokens(content);
    if (tokens.empty()) return;
    if (tokens[0] == "v") {
      // x y z, optionally w or r g b, which a rigid obstacle does not need.
      if (tokens.size() < 4) report.FailAt(line, "a vertex needs three coordinates");
      double values[3];
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        double value;
        std::string why;
        if (k <= 3 ? !ParseCoordinate(tokens[k], value, why) : !ParseDouble(tokens[k], value))
          report.FailAt(line, k <= 3 ? why : "bad number " + Quoted(tokens[k]) + " in vertex");
        if (k <= 3) values[k - 1] = value;
      }
      positions.emplace_back(values[0], values[1], values[2]);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) report.FailAt(line, "a face needs at least three vertices");
      Face face{{}, line};
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        // v, v/vt, v//vn or v/vt/vn: only v matters here, but all must be numbers.
        const std::string_view token = tokens[k];
        const std::string_view v = token.substr(0, token.find('/'));
        long long index;
        if (!ParseInt(v, index))
          report.FailAt(line, "bad vertex index " + Quoted(token) + " in face");
        for (std::size_t slash = token.find('/'); slash != std::string_view::npos;) {
          const std::size_t next = token.find('/', slash + 1);
          const std::string_view part = token.substr(slash + 1, next - slash - 1);
          long long ignored;
          if (!part.empty() && !ParseInt(part, ignored))
            report.FailAt(line, "bad index " + Quoted(token) + " in face");
          slash = next;
        }
        const long long count = static_cast<long long>(positions.size());
        if (index == 0) report.FailAt(line, "vertex index 0 in face (OBJ counts from 1)");
        // Negative indices count back from the last vertex read so far.
        const long long resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0)
          report.FailAt(line,
                        "vertex index " + std::to_string(index) + " is out of range (" +
                            Plural(positions.size(), "vertex", "vertices") + " so far)");
        face.corners.push_back(resolved);
      }
      faces.push_back(std::move(face));
    }
    // vt, vn, g, o, s, usemtl, mtllib, l, ...: nothing an obstacle needs.
  });

  RawMesh mesh;
  VertexMerger merger;
  std::vector<int> merged(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    merged[i] = merger.Add(positions[i], static_cast<int>(i) + 1, mesh);
  for (const Face& face : faces) {
    for (const long long corner : face.corners)
      if (corner >= static_cast<long long>(positions.size()))
        report.FailAt(face.line,
                      "vertex index " + std::to_string(corner + 1) + " is out of range (" +
                          Plural(positions.size(), "vertex", "vertices") + " in the file)");
    for (std::size_t k = 1; k + 1 < face.corners.size(); ++k) {
      mesh.triangles.push_back(
          {merged[face.corners[0]], merged[face.corners[k]], merged[face.corners[k + 1]]});
      mesh.triangle_line.push_back(face.line);
    }
  }
  return mesh;
}

RawMesh ReadAsciiStl(std::string_view text, const Reporter& report) {
  RawMesh mesh;
  VertexMerger merger;
  std::vector<int> loop;
  int facet_line = 0;
  ForEachLine(text, [&](int line, std::string_view content) {
    const std::vector<std::string_view> tokens = Tokens(content);
    if (tokens.empty()) return;
    const std::string_view keyword = tokens[0];
    if (keyword == "solid" || keyword == "endsolid" || keyword == "outer" ||
        keyword == "endfacet") {
      return;
    }
    if (keyword == "facet") {
      facet_line = line;
      loop.clear();
    } else if (keyword == "vertex") {
      double xyz[3];
      if (tokens.size() != 4) report.FailAt(line, "a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k) {
        std::string why;
        if (!ParseCoordinate(tokens[k + 1], xyz[k], why)) report.FailAt(line, why);
      }
      loop.push_back(
          merger.Add({xyz[0], xyz[1], xyz[2]}, static_cast<int>(mesh.vertices.size()) + 1, mesh));
    } else if (keyword == "endloop") {
      if (loop.size() < 3) report.FailAt(line, "a facet needs three vertices");
      for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
        mesh.triangles.push_back({loop[0], loop[k], loop[k + 1]});
        mesh.triangle_line.push_back(facet_line ? facet_line : line);
      }
      loop.clear();
    } else {
      report.FailAt(line, "unexpected " + Quoted(keyword) + " in ASCII STL");
    }
  });
  return mesh;
}

RawMesh ReadBinaryStl(std::string_view bytes) {
  static_assert(std::endian::native == std::endian::little, "binary STL is little-endian");
  RawMesh mesh;
  VertexMerger merger;
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
    std::array<int, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 + 12 * k, 12);  // after the facet normal
      triangle[k] =
          merger.Add({xyz[0], xyz[1], xyz[2]}, static_cast<int>(mesh.vertices.size()) + 1, mesh);
    }
    mesh.triangles.push_back(triangle);
    mesh.triangle_line.push_back(0);
  }
  return mesh;
}

RawMesh ReadStl(std::string_view bytes, const Reporter& report) {
  // The size is the reliable test: binary files may start with "solid" too.
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count)) {
      RawMesh mesh = ReadBinaryStl(bytes);
      for (const Vector3d& v : mesh.vertices)
        if (!v.allFinite()) report.Fail("a vertex coordinate is not a finite number");
      return mesh;
    }
  }
  const std::vector<std::string_view> first = Tokens(bytes.substr(0, bytes.find('\n')));
  if (!first.empty() && first[0] != "solid")
    report.Fail("neither ASCII STL (it does not start with 'solid') nor binary STL (its size " +
                std::to_string(bytes.size()) + " is not 84 + 50 per triangle)");
  return ReadAsciiStl(bytes, report);
}

std::string LowerCase(std::string text) {
  for (char& c : text)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

RawMesh ReadMesh(const std::filesystem::path& file, const Reporter& report) {
  const std::string extension = LowerCase(file.extension().string());
  if (extension != ".obj" && extension != ".stl")
    report.Fail("unknown mesh format " + Quoted(file.extension().string()) +
                " (expected .obj or .stl)");
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    report.Fail("cannot read mesh file " + Quoted(file.string()));
  std::ifstream in(file, std::ios::binary);
  if (!in) report.Fail("cannot read mesh file " + Quoted(file.string()));
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) report.Fail("cannot read mesh file " + Quoted(file.string()));
  return extension == ".obj" ? ReadObj(bytes, report) : ReadStl(bytes, report);
}

// ---- checks -----------------------------------------------------------------

// One triangle's side of an undirected edge: its local edge `local` runs
// from its corner `local` to corner `local + 1`.
struct HalfEdge {
  int lo, hi;  // the undirected edge, lo < hi
  int triangle;
  int local;
  bool forward;  // runs lo → hi
};

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

// ---- the geometry -----------------------------------------------------------

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
                                                           const std::string& where) {
  const Reporter report(file, where);
  RawMesh mesh = ReadMesh(file, report);
  const std::vector<HalfEdge> edges = CheckAndOrient(mesh, report);
  return std::make_unique<TriangleMeshGeometry>(mesh, edges);
}

}  // namespace drape
