// MeshDisk and MeshPolygon: all-quad meshes through Gmsh's C API, opened on
// first use (gmsh_api.h).
//
// Gmsh keeps global state, so every use is serialised by one mutex and each
// call runs in its own initialize ... finalize session (config files not
// read, so a user's gmshrc cannot change the mesh). Its output is then put
// into a canonical form that depends only on node positions, not on Gmsh's
// internal tags: nodes and elements numbered in rows of increasing y, then x;
// each quad counter-clockwise from +z and starting at its lowest node.
//
// Options, measured on Debian's Gmsh 4.8.4 over disks, an L and a concave
// cutting pattern with element sizes from 1/50 to 1/3 of the part:
// - Mesh.Algorithm 6 (Frontal-Delaunay). Algorithm 8 (Frontal-Delaunay for
//   quads) segfaults in this build: its cross field needs ANN, which Debian's
//   Gmsh is built without (MElementOctree::find on an unset octree).
// - Mesh.RecombinationAlgorithm 2 ("simple full-quad"): recombine, then split
//   every element into quads, so no triangle remains. Blossom (1, or 3 for
//   full-quad) gives slightly better angles but its time grows steeply (3 s
//   at 37 k quads, 170 s at 145 k); simple full-quad takes 8 s at 155 k.
//   Mesh.SubdivisionAlgorithm stays 0: full-quad has already split.
// - Worst measured: smallest angle 37°, largest 139°, aspect ratio 2.8; mean
//   edge 0.8–0.9 × element_size. Full-quad gives each curve a multiple of 4
//   segments (an even number before the split), so a curve only a few
//   element sizes long gets shorter edges than asked (a quarter arc of 5.2 h:
//   8 segments, mean edge 0.5 h).
// - General.AbortOnError 1: an error thrown inside Gmsh's OpenMP region
//   would terminate the process, so meshing stops and the error is read from
//   the logger instead.
#include "core/model/mesh.h"

#include "core/model/gmsh_api.h"
#include "core/model/polygon_checks.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <mutex>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

namespace drape {
namespace {

// Upper bound on the estimated element count (area / element_size²).
constexpr double kMaxEstimatedElements = 2e6;

constexpr double kPi = 3.14159265358979323846;

std::mutex& GmshMutex() {
  static std::mutex mutex;
  return mutex;
}

// Shortest text that reads back as `value` (0.1, not 0.10000000000000001).
std::string Format(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string Violation(const char* function,
                      const std::string& name,
                      double value,
                      const std::string& constraint) {
  return std::string(function) + ": " + name + " = " + Format(value) +
         ". Violated constraint: " + constraint;
}

void RequirePositiveFinite(const char* function, const char* name, double value) {
  if (!(std::isfinite(value) && value > 0))
    throw MeshError(Violation(function, name, value, "finite and > 0"));
}

void RequireFinite(const char* function, const std::string& name, double value) {
  if (!std::isfinite(value)) throw MeshError(Violation(function, name, value, "finite"));
}

void RequireFeasibleCount(const char* function, double area, double element_size) {
  const double estimate = area / (element_size * element_size);
  if (!(estimate <= kMaxEstimatedElements)) {
    throw MeshError(Violation(function,
                              "element_size",
                              element_size,
                              "area / element_size² <= " + Format(kMaxEstimatedElements) +
                                  " elements (the part's area is " + Format(area) +
                                  " m², which would need about " + Format(std::round(estimate)) +
                                  " elements)"));
  }
}

std::string Edge(std::size_t i, std::size_t n) {
  return "edge " + std::to_string(i) + " (vertices " + std::to_string(i) + "-" +
         std::to_string((i + 1) % n) + ")";
}

// Rejects what Gmsh cannot mesh or would mesh wrongly: too few vertices,
// non-finite or repeated vertices, an outline that folds back or crosses
// itself, no area. O(n²), which is nothing next to meshing.
void ValidateOutline(const std::vector<Eigen::Vector2d>& outline) {
  constexpr const char* kFunction = "MeshPolygon";
  const std::size_t n = outline.size();
  if (n < 3) {
    throw MeshError(Violation(
        kFunction, "outline.size()", static_cast<double>(n), "a polygon has at least 3 vertices"));
  }
  Eigen::Vector2d lo = outline[0], hi = outline[0];
  for (std::size_t i = 0; i < n; ++i) {
    RequireFinite(kFunction, "outline[" + std::to_string(i) + "].x", outline[i].x());
    RequireFinite(kFunction, "outline[" + std::to_string(i) + "].y", outline[i].y());
    lo = lo.cwiseMin(outline[i]);
    hi = hi.cwiseMax(outline[i]);
  }
  const double size = (hi - lo).norm();
  const double same_point = 1e-12 * size;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if ((outline[i] - outline[j]).norm() <= same_point) {
        throw MeshError(std::string(kFunction) + ": outline vertices " + std::to_string(i) +
                        " and " + std::to_string(j) + " are the same point (" +
                        Format(outline[i].x()) + ", " + Format(outline[i].y()) +
                        "); give each vertex once and do not close the outline");
      }
    }
  }
  const double zero = 1e-12 * size * size;
  for (std::size_t i = 0; i < n; ++i) {
    // Consecutive edges meet at vertex i + 1; they overlap if they are
    // collinear and leave that vertex in the same direction.
    const Eigen::Vector2d& a = outline[i];
    const Eigen::Vector2d& b = outline[(i + 1) % n];
    const Eigen::Vector2d& c = outline[(i + 2) % n];
    if (std::abs(Cross(a - b, c - b)) <= zero && (a - b).dot(c - b) > 0) {
      throw MeshError(std::string(kFunction) + ": the outline folds back on itself at vertex " +
                      std::to_string((i + 1) % n) + "; the outline must be a simple polygon");
    }
  }
  if (const auto crossing = FirstCrossing(outline, zero)) {
    throw MeshError(std::string(kFunction) + ": outline " + Edge(crossing->first, n) + " and " +
                    Edge(crossing->second, n) + " intersect; the outline must be a simple polygon");
  }
  if (!(std::abs(ShoelaceArea(outline)) > zero)) {
    throw MeshError(std::string(kFunction) + ": the outline encloses no area");
  }
}

// A hole must be a simple polygon lying inside the outline, clear of its
// edges and of the other holes.
void ValidateHole(const std::vector<Eigen::Vector2d>& outline,
                  const std::vector<std::vector<Eigen::Vector2d>>& holes,
                  std::size_t h) {
  const std::string which = "MeshPolygon: hole " + std::to_string(h);
  const std::vector<Eigen::Vector2d>& hole = holes[h];
  try {
    ValidateOutline(hole);
  } catch (const MeshError& e) {
    throw MeshError(which + ": " + e.what());
  }
  Eigen::Vector2d lo = outline[0], hi = outline[0];
  for (const auto& v : outline) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double zero = 1e-12 * (hi - lo).squaredNorm();
  auto edges_touch = [&](const std::vector<Eigen::Vector2d>& a,
                         const std::vector<Eigen::Vector2d>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j)
        if (SegmentsTouch(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], zero))
          return true;
    return false;
  };
  if (edges_touch(hole, outline))
    throw MeshError(which + " meets the outline; a hole must lie inside it, clear of its edges");
  if (!InsidePolygon(outline, hole[0])) throw MeshError(which + " lies outside the outline");
  for (std::size_t k = 0; k < holes.size(); ++k) {
    if (k == h) continue;
    if (edges_touch(hole, holes[k]) || InsidePolygon(holes[k], hole[0]))
      throw MeshError(which + " overlaps hole " + std::to_string(k));
  }
}

// For error messages: the outline's narrowest gap, the shortest distance from
// a vertex to an edge not incident to it (two disjoint segments are nearest at
// an endpoint of one of them), against the element size.
std::string NarrowestGapNote(const std::vector<Eigen::Vector2d>& outline, double element_size) {
  const std::size_t n = outline.size();
  double gap = std::numeric_limits<double>::infinity();
  std::size_t vertex = 0, edge = 0;
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t e = 0; e < n; ++e) {
      if (e == v || (e + 1) % n == v) continue;  // edge e runs from vertex e to e + 1
      const Eigen::Vector2d& a = outline[e];
      const Eigen::Vector2d& b = outline[(e + 1) % n];
      const double t = std::clamp((outline[v] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const double d = (a + t * (b - a) - outline[v]).norm();
      if (d < gap) {
        gap = d;
        vertex = v;
        edge = e;
      }
    }
  }
  if (!std::isfinite(gap)) return "";
  return "; the outline's narrowest gap is " + Format(gap) + " (vertex " + std::to_string(vertex) +
         " to " + Edge(edge, n) + ") against element_size = " + Format(element_size) +
         ": give an element_size well below that gap";
}

// Makes the end of an error message, only when there is an error.
using Note = std::function<std::string()>;

// What Gmsh returns, before canonical numbering.
struct RawMesh {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 4>> quads;
  std::size_t other_elements = 0;  // triangles or anything else that is not a 4-node quad
  std::string warnings;            // Gmsh's warnings, for error messages
};

// A C API call's error code: non-zero throws Gmsh's last error message.
void Check(int ierr, const char* call) {
  if (ierr == 0) return;
  const GmshApi& gmsh = Gmsh();
  char* error = nullptr;
  int ignored = 0;
  gmsh.LoggerGetLastError(&error, &ignored);
  std::string message = error ? error : "";
  if (error) gmsh.Free(error);
  if (message.empty()) message = std::string(call) + " returned error " + std::to_string(ierr);
  throw std::runtime_error(message);
}

// One initialize ... finalize session; the caller holds GmshMutex().
class GmshSession {
 public:
  GmshSession() : gmsh_(Gmsh()) {
    int ierr = 0;
    gmsh_.Initialize(0, nullptr, /*readConfigFiles=*/0, &ierr);
    Check(ierr, "gmshInitialize");
    gmsh_.LoggerStart(&ierr);
    Check(ierr, "gmshLoggerStart");
  }
  ~GmshSession() {
    int ierr = 0;
    gmsh_.LoggerStop(&ierr);
    gmsh_.Finalize(&ierr);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  // This session's messages that start with `level` ("Error", "Warning"),
  // joined by "; ".
  std::string Messages(const char* level) const {
    char** log = nullptr;
    std::size_t count = 0;
    int ierr = 0;
    gmsh_.LoggerGet(&log, &count, &ierr);
    std::string joined;
    for (std::size_t i = 0; i < count; ++i) {
      const std::string line = log[i];
      gmsh_.Free(log[i]);
      if (line.rfind(level, 0) == 0) joined += (joined.empty() ? "" : "; ") + line;
    }
    if (log) gmsh_.Free(log);
    return joined;
  }

 private:
  const GmshApi& gmsh_;
};

void SetOptions(const GmshApi& gmsh) {
  const std::pair<const char*, double> options[] = {
      {"General.Terminal", 0},             // silent
      {"General.Verbosity", 2},            // the logger keeps errors and warnings
      {"General.AbortOnError", 1},         // stop meshing, do not throw
      {"General.NumThreads", 1},           //
      {"Mesh.RandomSeed", 1},              //
      {"Mesh.Algorithm", 6},               // Frontal-Delaunay
      {"Mesh.RecombineAll", 1},            //
      {"Mesh.RecombinationAlgorithm", 2},  // simple full-quad
      {"Mesh.SubdivisionAlgorithm", 0},    // full-quad already splits
      {"Mesh.Smoothing", 1},               //
      {"Mesh.ElementOrder", 1},            //
      {"Mesh.MeshSizeFromPoints", 1},      //
      {"Mesh.MeshSizeFromCurvature", 0},   //
      {"Mesh.MeshSizeExtendFromBoundary", 1},
  };
  for (const auto& [name, value] : options) {
    int ierr = 0;
    gmsh.OptionSetNumber(name, value, &ierr);
    Check(ierr, name);
  }
}

// Gmsh's geo kernel, for the callers' curves: each call checked.
struct Geo {
  const GmshApi& gmsh;
  int Point(double x, double y, double mesh_size) const {
    int ierr = 0;
    const int tag = gmsh.GeoAddPoint(x, y, 0, mesh_size, -1, &ierr);
    Check(ierr, "gmshModelGeoAddPoint");
    return tag;
  }
  int Line(int start, int end) const {
    int ierr = 0;
    const int tag = gmsh.GeoAddLine(start, end, -1, &ierr);
    Check(ierr, "gmshModelGeoAddLine");
    return tag;
  }
  int Arc(int start, int center, int end) const {
    int ierr = 0;
    const int tag = gmsh.GeoAddCircleArc(start, center, end, -1, 0, 0, 0, &ierr);
    Check(ierr, "gmshModelGeoAddCircleArc");
    return tag;
  }
};

// The nodes and quads Gmsh made, into `raw`; the arrays it allocated freed.
void ReadMesh(const GmshApi& gmsh, RawMesh& raw) {
  std::size_t* node_tags = nullptr;
  double *coords = nullptr, *parametric = nullptr;
  std::size_t n_tags = 0, n_coords = 0, n_parametric = 0;
  int ierr = 0;
  gmsh.MeshGetNodes(
      &node_tags, &n_tags, &coords, &n_coords, &parametric, &n_parametric, -1, -1, 0, 0, &ierr);
  Check(ierr, "gmshModelMeshGetNodes");
  std::unordered_map<std::size_t, int> index;
  index.reserve(n_tags);
  raw.nodes.reserve(n_tags);
  for (std::size_t i = 0; i < n_tags; ++i) {
    index.emplace(node_tags[i], static_cast<int>(i));
    raw.nodes.emplace_back(coords[3 * i], coords[3 * i + 1]);
  }
  gmsh.Free(node_tags);
  gmsh.Free(coords);
  gmsh.Free(parametric);

  int* types = nullptr;
  std::size_t n_types = 0, n_lists = 0, n_node_lists = 0;
  std::size_t **element_tags = nullptr, **element_nodes = nullptr;
  std::size_t *element_counts = nullptr, *node_counts = nullptr;
  gmsh.MeshGetElements(&types,
                       &n_types,
                       &element_tags,
                       &element_counts,
                       &n_lists,
                       &element_nodes,
                       &node_counts,
                       &n_node_lists,
                       2,
                       -1,
                       &ierr);
  Check(ierr, "gmshModelMeshGetElements");
  for (std::size_t t = 0; t < n_types; ++t) {
    if (types[t] == 3) {  // 4-node quadrangle
      for (std::size_t e = 0; e < element_counts[t]; ++e) {
        std::array<int, 4> quad;
        for (int k = 0; k < 4; ++k) quad[k] = index.at(element_nodes[t][4 * e + k]);
        raw.quads.push_back(quad);
      }
    } else {
      raw.other_elements += element_counts[t];
    }
    gmsh.Free(element_tags[t]);
    gmsh.Free(element_nodes[t]);
  }
  gmsh.Free(types);
  gmsh.Free(element_tags);
  gmsh.Free(element_counts);
  gmsh.Free(element_nodes);
  gmsh.Free(node_counts);
}

// What a plane surface is made of, as tags of the geo kernel: its curve
// loops (the outer boundary, then each hole), and the curves and points
// embedded in it.
struct SurfaceCurves {
  std::vector<std::vector<int>> loops;
  std::vector<int> embedded_curves;
  std::vector<int> embedded_points;
};

// Gmsh embeds entities in a surface only once the model holds both.
void Embed(const GmshApi& gmsh, int dim, std::vector<int> tags, int surface) {
  if (tags.empty()) return;
  int ierr = 0;
  gmsh.MeshEmbed(dim, tags.data(), tags.size(), 2, surface, &ierr);
  Check(ierr, "gmshModelMeshEmbed");
}

// Meshes the plane surface made of the curves `add_curves(geo)` adds to the
// geo kernel (a SurfaceCurves); the curves' points carry the mesh size.
// `note()` ends error messages.
template <typename AddCurves>
RawMesh RunGmsh(const char* function, const Note& note, AddCurves add_curves) {
  std::lock_guard<std::mutex> lock(GmshMutex());
  RawMesh raw;
  std::string errors;
  try {
    const GmshApi& gmsh = Gmsh();
    GmshSession session;
    SetOptions(gmsh);
    int ierr = 0;
    gmsh.ModelAdd("drape", &ierr);
    Check(ierr, "gmshModelAdd");
    SurfaceCurves surface_curves = add_curves(Geo{gmsh});
    std::vector<int> wires;
    for (std::vector<int>& curves : surface_curves.loops) {
      wires.push_back(gmsh.GeoAddCurveLoop(curves.data(), curves.size(), -1, 0, &ierr));
      Check(ierr, "gmshModelGeoAddCurveLoop");
    }
    const int surface = gmsh.GeoAddPlaneSurface(wires.data(), wires.size(), -1, &ierr);
    Check(ierr, "gmshModelGeoAddPlaneSurface");
    gmsh.GeoMeshSetRecombine(2, surface, 45, &ierr);
    Check(ierr, "gmshModelGeoMeshSetRecombine");
    gmsh.GeoSynchronize(&ierr);
    Check(ierr, "gmshModelGeoSynchronize");
    Embed(gmsh, 1, surface_curves.embedded_curves, surface);
    Embed(gmsh, 0, surface_curves.embedded_points, surface);
    gmsh.MeshGenerate(2, &ierr);
    errors = session.Messages("Error");
    raw.warnings = session.Messages("Warning");
    if (errors.empty()) Check(ierr, "gmshModelMeshGenerate");
    if (errors.empty()) ReadMesh(gmsh, raw);
  } catch (const std::exception& e) {
    errors += (errors.empty() ? "" : "; ") + std::string(e.what());
  }
  if (!errors.empty()) throw MeshError(std::string(function) + ": Gmsh failed: " + errors + note());
  if (raw.quads.empty())
    throw MeshError(std::string(function) + ": Gmsh returned no quads" + note());
  return raw;
}

// Full-quad recombination splits every edge at its middle, but Gmsh 4.8
// gives the middle of an embedded line's edge to the surface, not the line,
// and smoothing then moves it off the line (by 0.07 of the element size on
// a 40 × 30 square meshed at 5 cm). Such a node has quad edges to two nodes
// on the segment, one each side of it; it is put back on the segment.
void ReturnMiddlesToSegments(RawMesh& raw,
                             const std::vector<std::array<Eigen::Vector2d, 2>>& segments,
                             double element_size) {
  if (segments.empty()) return;
  std::vector<std::vector<int>> neighbours(raw.nodes.size());
  for (const auto& quad : raw.quads)
    for (int k = 0; k < 4; ++k) {
      neighbours[quad[k]].push_back(quad[(k + 1) % 4]);
      neighbours[quad[(k + 1) % 4]].push_back(quad[k]);
    }
  const double on = 1e-12 * element_size, near = 0.25 * element_size;
  for (const auto& [a, b] : segments) {
    const Eigen::Vector2d ab = b - a;
    auto along = [&](int n) { return (raw.nodes[n] - a).dot(ab) / ab.squaredNorm(); };
    auto off = [&](int n) {
      const double t = std::clamp(along(n), 0.0, 1.0);
      return (a + t * ab - raw.nodes[n]).norm();
    };
    for (std::size_t n = 0; n < raw.nodes.size(); ++n) {
      const double t = along(static_cast<int>(n));
      const double d = off(static_cast<int>(n));
      if (d <= on || d > near || t <= 0 || t >= 1) continue;
      bool before = false, after = false;
      for (int m : neighbours[n])
        if (off(m) <= on) (along(m) < t ? before : after) = true;
      if (before && after) raw.nodes[n] = a + t * ab;
    }
  }
}

// Indices of `points` in rows of increasing y (points whose y is within `tol`
// of the row's first y form one row), each row in increasing x.
std::vector<int> RowOrder(const std::vector<Eigen::Vector2d>& points, double tol) {
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  auto by_y = [&](int a, int b) {
    if (points[a].y() != points[b].y()) return points[a].y() < points[b].y();
    return points[a].x() < points[b].x();
  };
  auto by_x = [&](int a, int b) {
    if (points[a].x() != points[b].x()) return points[a].x() < points[b].x();
    return points[a].y() < points[b].y();
  };
  std::stable_sort(order.begin(), order.end(), by_y);
  for (std::size_t first = 0; first < order.size();) {
    std::size_t last = first + 1;
    while (last < order.size() && points[order[last]].y() - points[order[first]].y() <= tol) ++last;
    std::stable_sort(order.begin() + first, order.begin() + last, by_x);
    first = last;
  }
  return order;
}

// Checks that Gmsh gave only strictly convex quads, then numbers them
// canonically. `note()` ends error messages.
Mesh Canonical(const char* function, const RawMesh& raw, double elevation, const Note& note) {
  const std::string gmsh_says = raw.warnings.empty() ? "" : " (Gmsh: " + raw.warnings + ")";
  if (raw.other_elements > 0) {
    // Full-quad recombination splits every element into quads; only an
    // outline far narrower somewhere than element_size has left others.
    throw MeshError(std::string(function) + ": Gmsh left " + std::to_string(raw.other_elements) +
                    " elements that are not quads" + note() + gmsh_says);
  }
  // Keep only nodes that some quad uses (the disk's centre point, for one, is not).
  std::vector<char> used(raw.nodes.size(), 0);
  for (const auto& quad : raw.quads)
    for (int n : quad) used[n] = 1;
  std::vector<int> kept;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (std::size_t n = 0; n < raw.nodes.size(); ++n) {
    if (!used[n]) continue;
    kept.push_back(static_cast<int>(n));
    lo = lo.cwiseMin(raw.nodes[n]);
    hi = hi.cwiseMax(raw.nodes[n]);
  }
  const double tol = 1e-9 * (hi - lo).norm();

  std::vector<Eigen::Vector2d> points;
  points.reserve(kept.size());
  for (int n : kept) points.push_back(raw.nodes[n]);
  const std::vector<int> node_order = RowOrder(points, tol);
  std::vector<int> new_index(raw.nodes.size(), -1);
  Mesh mesh;
  mesh.positions.resize(static_cast<Eigen::Index>(node_order.size()), 3);
  for (std::size_t i = 0; i < node_order.size(); ++i) {
    const int old = kept[node_order[i]];
    new_index[old] = static_cast<int>(i);
    mesh.positions.row(i) << raw.nodes[old].x(), raw.nodes[old].y(), elevation;
  }

  std::vector<std::array<int, 4>> quads;
  std::vector<Eigen::Vector2d> centroids;
  quads.reserve(raw.quads.size());
  centroids.reserve(raw.quads.size());
  int non_convex = 0;
  for (const auto& raw_quad : raw.quads) {
    std::array<int, 4> q;
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    double twice_area = 0;
    for (int k = 0; k < 4; ++k) {
      q[k] = new_index[raw_quad[k]];
      centroid += 0.25 * raw.nodes[raw_quad[k]];
      twice_area += Cross(raw.nodes[raw_quad[k]], raw.nodes[raw_quad[(k + 1) % 4]]);
    }
    const double sense = twice_area < 0 ? -1.0 : 1.0;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d& corner = raw.nodes[raw_quad[k]];
      const double turn = sense * Cross(raw.nodes[raw_quad[(k + 1) % 4]] - corner,
                                        raw.nodes[raw_quad[(k + 3) % 4]] - corner);
      if (!(turn > 0)) {
        ++non_convex;
        break;
      }
    }
    if (twice_area < 0) std::swap(q[1], q[3]);  // now counter-clockwise from +z
    std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
    quads.push_back(q);
    centroids.push_back(centroid);
  }
  if (non_convex > 0) {
    throw MeshError(std::string(function) + ": Gmsh made " + std::to_string(non_convex) +
                    " quads that are degenerate or not convex" + note() + gmsh_says);
  }
  const std::vector<int> element_order = RowOrder(centroids, tol);
  mesh.quads.resize(static_cast<Eigen::Index>(element_order.size()), 4);
  for (std::size_t e = 0; e < element_order.size(); ++e) {
    const auto& q = quads[element_order[e]];
    mesh.quads.row(e) << q[0], q[1], q[2], q[3];
  }
  return mesh;
}

}  // namespace

Mesh MeshDisk(double radius, const Eigen::Vector2d& center, double element_size, double elevation) {
  constexpr const char* kFunction = "MeshDisk";
  RequirePositiveFinite(kFunction, "radius", radius);
  RequireFinite(kFunction, "center.x", center.x());
  RequireFinite(kFunction, "center.y", center.y());
  RequirePositiveFinite(kFunction, "element_size", element_size);
  RequireFinite(kFunction, "elevation", elevation);
  RequireFeasibleCount(kFunction, kPi * radius * radius, element_size);

  const Note note = [] { return std::string(); };
  const RawMesh raw = RunGmsh(kFunction, note, [&](const Geo& geo) {
    const double cx = center.x(), cy = center.y(), h = element_size;
    const int c = geo.Point(cx, cy, h);
    // Four quarter arcs: the geo kernel's arcs must be shorter than π.
    const int p[4] = {geo.Point(cx + radius, cy, h),
                      geo.Point(cx, cy + radius, h),
                      geo.Point(cx - radius, cy, h),
                      geo.Point(cx, cy - radius, h)};
    std::vector<int> arcs;
    for (int k = 0; k < 4; ++k) arcs.push_back(geo.Arc(p[k], c, p[(k + 1) % 4]));
    return SurfaceCurves{{arcs}, {}, {}};
  });
  return Canonical(kFunction, raw, elevation, note);
}

Mesh MeshPolygon(const std::vector<Eigen::Vector2d>& outline,
                 double element_size,
                 double elevation,
                 const MeshFeatures& features) {
  constexpr const char* kFunction = "MeshPolygon";
  const auto& holes = features.holes;
  ValidateOutline(outline);
  for (std::size_t h = 0; h < holes.size(); ++h) ValidateHole(outline, holes, h);
  RequirePositiveFinite(kFunction, "element_size", element_size);
  RequireFinite(kFunction, "elevation", elevation);
  double area = std::abs(ShoelaceArea(outline));
  for (const auto& hole : holes) area -= std::abs(ShoelaceArea(hole));
  RequireFeasibleCount(kFunction, area, element_size);

  const PlanarGraph graph = BuildPlanarGraph(outline, features, 0.25 * element_size);

  const Note note = [&] { return NarrowestGapNote(outline, element_size); };
  RawMesh raw = RunGmsh(kFunction, note, [&](const Geo& geo) {
    std::vector<int> points;
    for (const auto& v : graph.vertices) points.push_back(geo.Point(v.x(), v.y(), element_size));
    SurfaceCurves curves;
    for (const auto& loop : graph.loops) {
      std::vector<int> lines;
      for (std::size_t i = 0; i < loop.size(); ++i)
        lines.push_back(geo.Line(points[loop[i]], points[loop[(i + 1) % loop.size()]]));
      curves.loops.push_back(lines);
    }
    for (const auto& s : graph.segments)
      curves.embedded_curves.push_back(geo.Line(points[s[0]], points[s[1]]));
    for (int v : graph.points) curves.embedded_points.push_back(points[v]);
    return curves;
  });
  std::vector<std::array<Eigen::Vector2d, 2>> segments;
  for (const auto& s : graph.segments)
    segments.push_back({graph.vertices[s[0]], graph.vertices[s[1]]});
  ReturnMiddlesToSegments(raw, segments, element_size);
  return Canonical(kFunction, raw, elevation, note);
}

}  // namespace drape
