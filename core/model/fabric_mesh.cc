#include "core/model/fabric_mesh.h"

#include <algorithm>
#include <cmath>

#include "core/model/imperfection.h"
#include "core/model/outline_geometry.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

std::vector<Eigen::Vector2d> Points(const std::vector<Vec2>& vertices) {
  std::vector<Eigen::Vector2d> points;
  for (const auto& v : vertices) points.emplace_back(v[0], v[1]);
  return points;
}

// What a piece's mesh follows: its cut-outs open, element edges along its
// internal lines, and a node at each notch and drill hole, so that the
// selections naming them pick the very point.
MeshFeatures PieceFeatures(const PatternPiece& piece) {
  MeshFeatures features;
  for (const auto& hole : piece.holes) features.holes.push_back(Points(hole));
  for (std::size_t k = 0; k < piece.internal_lines.size(); ++k)
    features.lines.push_back(
        {Points(piece.internal_lines[k]), "internal line " + std::to_string(k + 1) + " (layer 8)"});
  for (std::size_t k = 0; k < piece.notches.size(); ++k) {
    const auto& p = piece.notches[k];
    features.points.push_back({{p[0], p[1]}, "notch " + std::to_string(k + 1)});
  }
  for (std::size_t k = 0; k < piece.drills.size(); ++k) {
    const auto& p = piece.drills[k];
    features.points.push_back({{p[0], p[1]}, "drill hole " + std::to_string(k + 1)});
  }
  return features;
}

}  // namespace

Mesh MeshFabricParts(const Scene& scene) {
  if (scene.other_parts.empty()) return MeshFabric(scene.fabric);
  std::vector<Mesh> meshes;
  const auto parts = FabricParts(scene);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    try {
      meshes.push_back(MeshFabric(*parts[p]));
    } catch (const SceneError& e) {
      // "fabric.outline" → "fabric[p].outline"
      throw SceneError("fabric[" + std::to_string(p) + "]" + e.where().substr(6), e.message());
    }
  }
  return JoinedMesh(meshes);
}

Eigen::VectorXd PartElevations(const Scene& scene, const Mesh& mesh) {
  Eigen::VectorXd z(mesh.NodeCount());
  const auto parts = FabricParts(scene);
  const auto spans = PartsOf(mesh);
  for (std::size_t p = 0; p < spans.size(); ++p)
    z.segment(spans[p].first_node, spans[p].nodes)
        .setConstant(parts[std::min(p, parts.size() - 1)]->elevation);
  return z;
}

std::array<int, 2> RectangleElementCounts(const RectangleOutline& rectangle, double element_size) {
  auto count = [&](double length) {
    return std::max(1, static_cast<int>(std::lround(length / element_size)));
  };
  return {count(rectangle.size[0]), count(rectangle.size[1])};
}

Mesh MeshFabric(const Fabric& fabric) {
  Mesh mesh;
  try {
    if (const auto* r = std::get_if<RectangleOutline>(&fabric.outline)) {
      auto n = fabric.mesh.elements ? *fabric.mesh.elements
                                    : RectangleElementCounts(*r, *fabric.mesh.size);
      mesh = MeshRectangle(
          r->size[0], r->size[1], {r->center[0], r->center[1]}, n[0], n[1], fabric.elevation);
    } else if (const auto* d = std::get_if<DiskOutline>(&fabric.outline)) {
      mesh = MeshDisk(d->radius, {d->center[0], d->center[1]}, *fabric.mesh.size, fabric.elevation);
    } else if (const auto* p = std::get_if<PolygonOutline>(&fabric.outline)) {
      mesh = MeshPolygon(Points(p->vertices), *fabric.mesh.size, fabric.elevation);
    } else {
      const PatternPiece& piece = std::get<PatternOutline>(fabric.outline).shape;
      mesh = MeshPolygon(
          Points(piece.boundary), *fabric.mesh.size, fabric.elevation, PieceFeatures(piece));
    }
  } catch (const MeshError& e) {
    const bool shaped = std::holds_alternative<PolygonOutline>(fabric.outline) ||
                        std::holds_alternative<PatternOutline>(fabric.outline);
    throw SceneError(shaped ? "fabric.outline" : "fabric.mesh", e.what());
  }
  if (fabric.imperfection && fabric.imperfection->amplitude > 0) {
    const ImperfectionSpec& spec = *fabric.imperfection;
    Bounds2 b = OutlineBounds(fabric.outline);
    double wavelength =
        spec.wavelength.value_or(0.25 * std::max(b.max[0] - b.min[0], b.max[1] - b.min[1]));
    Eigen::Matrix<double, Eigen::Dynamic, 2> xy = mesh.positions.leftCols<2>();
    mesh.positions.col(2).array() +=
        ImperfectionOffsets(xy, spec.amplitude, spec.seed, spec.pattern, wavelength).array();
  }
  return mesh;
}

}  // namespace drape
