#include "core/model/node_selection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/model/outline_geometry.h"
#include "core/model/overloaded.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

Vec2 XY(const Mesh& mesh, int i) {
  return {mesh.positions(i, 0), mesh.positions(i, 1)};
}

int NearestNode(const Mesh& mesh, const Vec2& p) {
  int best = 0;
  double best_d2 = INFINITY;
  for (int i = 0; i < mesh.NodeCount(); ++i) {
    Vec2 q = XY(mesh, i);
    double d2 = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]);
    if (d2 < best_d2) {  // strict: ties go to the lowest index
      best = i;
      best_d2 = d2;
    }
  }
  return best;
}

std::string Length(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x << " m";
  return s.str();
}

std::string Point(const Vec2& p) {
  std::ostringstream s;
  s << "(" << p[0] << ", " << p[1] << ") m";
  return s.str();
}

template <typename Keep>
std::vector<int> NodesWhere(const Mesh& mesh, Keep keep) {
  std::vector<int> nodes;
  for (int i = 0; i < mesh.NodeCount(); ++i)
    if (keep(XY(mesh, i))) nodes.push_back(i);
  return nodes;
}

}  // namespace

double DefaultSelectionTolerance(const Outline& outline) {
  return 1e-6 * OutlineSize(outline);
}

std::vector<int> BoundaryNodes(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> edge_uses;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      int a = mesh.quads(e, k), b = mesh.quads(e, (k + 1) % 4);
      ++edge_uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<int> nodes;
  for (const auto& [edge, uses] : edge_uses)
    if (uses == 1) {
      nodes.push_back(edge.first);
      nodes.push_back(edge.second);
    }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<int> SelectNodes(const Selection& selection, const Mesh& mesh, const Outline& outline) {
  const double tol = selection.tolerance.value_or(DefaultSelectionTolerance(outline));
  std::vector<int> nodes = std::visit(
      Overloaded{
          [&](const PointSelection& p) {
            if (double d = DistanceToOutline(outline, p.at); d > tol)
              throw SelectionError("point " + Point(p.at) + " lies " + Length(d) +
                                   " outside the fabric");
            return std::vector<int>{NearestNode(mesh, p.at)};
          },
          [&](const LineSelection& l) {
            return NodesWhere(
                mesh, [&](const Vec2& q) { return DistanceToSegment(q, l.from, l.to) <= tol; });
          },
          [&](const BoxSelection& b) {
            return NodesWhere(mesh, [&](const Vec2& q) {
              return q[0] >= b.min[0] - tol && q[0] <= b.max[0] + tol && q[1] >= b.min[1] - tol &&
                     q[1] <= b.max[1] + tol;
            });
          },
          [&](const CircleSelection& c) {
            return NodesWhere(mesh, [&](const Vec2& q) {
              return std::hypot(q[0] - c.center[0], q[1] - c.center[1]) <= c.radius + tol;
            });
          },
          [&](const CornersSelection&) {
            auto corners = OutlineCorners(outline);
            if (corners.empty()) throw SelectionError("a disk has no corners");
            std::vector<int> out;
            for (const auto& c : corners) out.push_back(NearestNode(mesh, c));
            return out;
          },
          [&](const EdgeSelection& e) {
            if (e.side == Side::kBoundary) return BoundaryNodes(mesh);
            Bounds2 b = OutlineBounds(outline);
            return NodesWhere(mesh, [&](const Vec2& q) {
              switch (e.side) {
                case Side::kLeft:
                  return q[0] <= b.min[0] + tol;
                case Side::kRight:
                  return q[0] >= b.max[0] - tol;
                case Side::kBottom:
                  return q[1] <= b.min[1] + tol;
                default:
                  return q[1] >= b.max[1] - tol;
              }
            });
          },
          [&](const NodesSelection& n) {
            for (int i : n.nodes)
              if (i >= mesh.NodeCount())
                throw SelectionError("node " + std::to_string(i) +
                                     " does not exist; the mesh has " +
                                     std::to_string(mesh.NodeCount()) + " nodes (0 to " +
                                     std::to_string(mesh.NodeCount() - 1) + ")");
            return n.nodes;
          },
          [&](const PatternMarkSelection& m) {
            const auto* pattern = std::get_if<PatternOutline>(&outline);
            const std::string what = PatternMarkName(m.mark);
            if (!pattern)
              throw SelectionError("a " + what +
                                   " is a pattern piece's; this fabric's outline is not one");
            const PatternPiece& piece = pattern->shape;
            const std::size_t count = m.mark == PatternMark::kNotch   ? piece.notches.size()
                                      : m.mark == PatternMark::kDrill ? piece.drills.size()
                                                                      : piece.internal_lines.size();
            if (m.index > static_cast<int>(count))
              throw SelectionError(what + " " + std::to_string(m.index) +
                                   " does not exist; piece '" + pattern->piece + "' has " +
                                   std::to_string(count) + " " + what +
                                   (m.mark == PatternMark::kNotch ? "es" : "s") +
                                   (count == 0 ? "" : " (1 to " + std::to_string(count) + ")"));
            if (m.mark == PatternMark::kInternalLine) {
              const PieceLine& line = piece.internal_lines[m.index - 1];
              return NodesWhere(mesh, [&](const Vec2& q) {
                for (std::size_t i = 0; i + 1 < line.size(); ++i)
                  if (DistanceToSegment(q, line[i], line[i + 1]) <= tol) return true;
                return false;
              });
            }
            const auto& marks = m.mark == PatternMark::kNotch ? piece.notches : piece.drills;
            return std::vector<int>{NearestNode(mesh, marks[m.index - 1])};
          },
      },
      selection.shape);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<int> SelectNodesInParts(const Selection& selection,
                                    const Scene& scene,
                                    const Mesh& mesh) {
  const auto parts = FabricParts(scene);
  if (parts.size() == 1 || std::holds_alternative<NodesSelection>(selection.shape))
    return SelectNodes(selection, mesh, scene.fabric.outline);
  const auto spans = PartsOf(mesh);
  std::vector<int> all;
  std::vector<std::string> hit;
  std::optional<SelectionError> first_error;
  for (std::size_t p = 0; p < parts.size() && p < spans.size(); ++p) {
    if (selection.part && *selection.part != parts[p]->name) continue;
    std::vector<int> nodes;
    try {
      nodes = SelectNodes(selection, PartMesh(mesh, spans[p]), parts[p]->outline);
    } catch (const SelectionError& e) {
      // Unnamed, a point or a mark belongs to the parts that have it.
      if (selection.part) throw;
      if (!first_error) first_error = e;
      continue;
    }
    if (!nodes.empty()) hit.push_back(parts[p]->name);
    for (int n : nodes) all.push_back(n + spans[p].first_node);
  }
  if (hit.empty() && first_error) throw *first_error;
  const auto* mark = std::get_if<PatternMarkSelection>(&selection.shape);
  const bool one_node = std::holds_alternative<PointSelection>(selection.shape) ||
                        (mark && mark->mark != PatternMark::kInternalLine);
  if (one_node && hit.size() > 1)
    throw SelectionError("it picks a node in each of the parts '" + hit[0] + "' and '" + hit[1] +
                         "', which lie over each other there; name one with \"part\"");
  return all;
}

std::vector<std::string> PartsAt(const Scene& scene, const Vec2& at, double tol) {
  std::vector<std::string> names;
  for (const Fabric* part : FabricParts(scene))
    if (DistanceToOutline(part->outline, at) <= tol) names.push_back(part->name);
  return names;
}

std::vector<ResolvedSelection> ResolveSelections(const Scene& scene, const Mesh& mesh) {
  std::vector<ResolvedSelection> resolved;
  auto resolve = [&](const std::string& path, const std::string& name, const Selection& s) {
    std::vector<int> nodes;
    try {
      nodes = SelectNodesInParts(s, scene, mesh);
    } catch (const SelectionError& e) {
      throw SceneError(path, e.what());
    }
    if (nodes.empty()) {
      double tol = s.tolerance.value_or(DefaultSelectionTolerance(scene.fabric.outline));
      throw SceneError(path,
                       "'" + name + "' matched no node (tolerance " + Length(tol) +
                           "); check its coordinates or give a larger 'tolerance'");
    }
    resolved.push_back({path, name, std::move(nodes)});
  };
  for (size_t i = 0; i < scene.supports.size(); ++i)
    resolve("supports[" + std::to_string(i) + "].select",
            scene.supports[i].name,
            scene.supports[i].select);
  for (size_t i = 0; i < scene.grippers.size(); ++i)
    resolve("grippers[" + std::to_string(i) + "].select",
            scene.grippers[i].name,
            scene.grippers[i].select);
  for (size_t i = 0; i < scene.loads.size(); ++i)
    resolve("loads[" + std::to_string(i) + "].select", scene.loads[i].name, scene.loads[i].select);

  double tol = DefaultSelectionTolerance(scene.fabric.outline);
  for (size_t i = 0; i < scene.probes.size(); ++i) {
    const Probe& p = scene.probes[i];
    if (scene.other_parts.empty()) {
      if (double d = DistanceToOutline(scene.fabric.outline, p.at); d > tol)
        throw SceneError("probes[" + std::to_string(i) + "].at",
                         "probe '" + p.name + "' at " + Point(p.at) + " lies " + Length(d) +
                             " outside the fabric");
      continue;
    }
    const auto on = PartsAt(scene, p.at, tol);
    const std::string where = "probes[" + std::to_string(i) + "]";
    if (p.part && std::find(on.begin(), on.end(), *p.part) == on.end())
      throw SceneError(
          where + ".at",
          "probe '" + p.name + "' at " + Point(p.at) + " lies outside part '" + *p.part + "'");
    if (on.empty())
      throw SceneError(
          where + ".at",
          "probe '" + p.name + "' at " + Point(p.at) + " lies on no part of the fabric");
    if (!p.part && on.size() > 1)
      throw SceneError(where,
                       "probe '" + p.name + "' at " + Point(p.at) + " lies on the parts '" + on[0] +
                           "' and '" + on[1] + "', over each other there; name one with \"part\"");
  }
  return resolved;
}

}  // namespace drape
