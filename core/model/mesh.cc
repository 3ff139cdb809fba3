#include "core/model/mesh.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace drape {
namespace {

// Shortest text that reads back as `value` (0.1, not 0.10000000000000001).
std::string Format(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string Quoted(const char* function, const char* name, double value, const char* constraint) {
  return std::string(function) + ": " + name + " = " + Format(value) +
         ". Violated constraint: " + constraint;
}

void RequirePositiveFinite(const char* function, const char* name, double value) {
  if (!(std::isfinite(value) && value > 0))
    throw MeshError(Quoted(function, name, value, "finite and > 0"));
}

void RequireFinite(const char* function, const char* name, double value) {
  if (!std::isfinite(value)) throw MeshError(Quoted(function, name, value, "finite"));
}

// Twice the signed area of the quad's projection on the xy plane (shoelace).
double TwiceSignedArea(const Mesh& mesh, int e) {
  double twice = 0;
  for (int k = 0; k < 4; ++k) {
    const int a = mesh.quads(e, k);
    const int b = mesh.quads(e, (k + 1) % 4);
    twice +=
        mesh.positions(a, 0) * mesh.positions(b, 1) - mesh.positions(b, 0) * mesh.positions(a, 1);
  }
  return twice;
}

}  // namespace

Mesh MeshRectangle(
    double size_x, double size_y, const Eigen::Vector2d& center, int nx, int ny, double elevation) {
  constexpr const char* kFunction = "MeshRectangle";
  RequirePositiveFinite(kFunction, "size_x", size_x);
  RequirePositiveFinite(kFunction, "size_y", size_y);
  if (nx < 1) throw MeshError(Quoted(kFunction, "nx", nx, "nx >= 1"));
  if (ny < 1) throw MeshError(Quoted(kFunction, "ny", ny, "ny >= 1"));
  RequireFinite(kFunction, "center.x", center.x());
  RequireFinite(kFunction, "center.y", center.y());
  RequireFinite(kFunction, "elevation", elevation);
  const std::int64_t node_count = (std::int64_t{nx} + 1) * (std::int64_t{ny} + 1);
  if (node_count > std::numeric_limits<int>::max())
    throw MeshError(Quoted(kFunction,
                           "(nx + 1) * (ny + 1)",
                           static_cast<double>(node_count),
                           "node count fits in an int"));

  Mesh mesh;
  mesh.positions.resize(node_count, 3);
  const double x0 = center.x() - 0.5 * size_x;
  const double y0 = center.y() - 0.5 * size_y;
  // The fraction i / nx is rounded once, so a node at the same fraction gets
  // bitwise the same coordinate at every density (nx = 10 and 40 share nodes).
  for (int j = 0; j <= ny; ++j) {
    const double y = y0 + size_y * (static_cast<double>(j) / ny);
    for (int i = 0; i <= nx; ++i) {
      const int n = j * (nx + 1) + i;
      mesh.positions(n, 0) = x0 + size_x * (static_cast<double>(i) / nx);
      mesh.positions(n, 1) = y;
      mesh.positions(n, 2) = elevation;
    }
  }
  mesh.quads.resize(static_cast<Eigen::Index>(nx) * ny, 4);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int e = j * nx + i;
      const int n = j * (nx + 1) + i;
      mesh.quads.row(e) << n, n + 1, n + nx + 2, n + nx + 1;  // counter-clockwise from +z
    }
  }
  return mesh;
}

std::vector<MeshPart> PartsOf(const Mesh& mesh) {
  if (!mesh.parts.empty()) return mesh.parts;
  return {MeshPart{0, mesh.NodeCount(), 0, mesh.ElementCount()}};
}

Mesh PartMesh(const Mesh& mesh, const MeshPart& part) {
  Mesh out;
  out.positions = mesh.positions.middleRows(part.first_node, part.nodes);
  out.quads = mesh.quads.middleRows(part.first_element, part.elements).array() - part.first_node;
  return out;
}

Mesh JoinedMesh(const std::vector<Mesh>& parts) {
  Mesh out;
  int nodes = 0, elements = 0;
  for (const Mesh& m : parts) {
    out.parts.push_back({nodes, m.NodeCount(), elements, m.ElementCount()});
    nodes += m.NodeCount();
    elements += m.ElementCount();
  }
  out.positions.resize(nodes, 3);
  out.quads.resize(elements, 4);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const MeshPart& span = out.parts[p];
    out.positions.middleRows(span.first_node, span.nodes) = parts[p].positions;
    out.quads.middleRows(span.first_element, span.elements) =
        parts[p].quads.array() + span.first_node;
  }
  return out;
}

double ProjectedArea(const Mesh& mesh) {
  double twice = 0;
  for (int e = 0; e < mesh.ElementCount(); ++e) twice += TwiceSignedArea(mesh, e);
  return 0.5 * twice;
}

double MeanEdgeLength(const Mesh& mesh) {
  if (mesh.ElementCount() == 0) return 0;
  double sum = 0;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      sum += (mesh.positions.row(mesh.quads(e, (k + 1) % 4)) - mesh.positions.row(mesh.quads(e, k)))
                 .norm();
  return sum / (4.0 * mesh.ElementCount());
}

MeshQuality MeasureQuality(const Mesh& mesh) {
  MeshQuality quality;
  if (mesh.ElementCount() == 0) return quality;
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  quality.min_angle_deg = std::numeric_limits<double>::infinity();
  quality.max_angle_deg = -std::numeric_limits<double>::infinity();
  quality.min_signed_area = std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    const double area = 0.5 * TwiceSignedArea(mesh, e);
    quality.min_signed_area = std::min(quality.min_signed_area, area);
    // Interior angles are measured in the quad's own turning sense, so a
    // clockwise quad has the same angles as its counter-clockwise mirror and a
    // re-entrant corner reads more than 180°.
    const double sense = area < 0 ? -1.0 : 1.0;
    double shortest = std::numeric_limits<double>::infinity();
    double longest = 0;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d corner = mesh.positions.row(mesh.quads(e, k)).head<2>();
      const Eigen::Vector2d next =
          mesh.positions.row(mesh.quads(e, (k + 1) % 4)).head<2>().transpose() - corner;
      const Eigen::Vector2d previous =
          mesh.positions.row(mesh.quads(e, (k + 3) % 4)).head<2>().transpose() - corner;
      double angle = std::atan2(sense * (next.x() * previous.y() - next.y() * previous.x()),
                                next.dot(previous)) *
                     kDegrees;
      if (angle < 0) angle += 360.0;
      quality.min_angle_deg = std::min(quality.min_angle_deg, angle);
      quality.max_angle_deg = std::max(quality.max_angle_deg, angle);
      const double edge = next.norm();
      shortest = std::min(shortest, edge);
      longest = std::max(longest, edge);
    }
    const double ratio =
        shortest > 0 ? longest / shortest : std::numeric_limits<double>::infinity();
    quality.max_aspect_ratio = std::max(quality.max_aspect_ratio, ratio);
  }
  return quality;
}

}  // namespace drape
