#include "core/fe/edge_moments.h"

#include <algorithm>
#include <set>
#include <utility>

namespace drape {
namespace {

bool AreEdgeNeighbours(const Mesh& mesh, int a, int b) {
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      const int p = mesh.quads(e, k), q = mesh.quads(e, (k + 1) % 4);
      if ((p == a && q == b) || (p == b && q == a)) return true;
    }
  return false;
}

// The nodes sorted along their common line and its unit axis, or nothing if
// they are fewer than two, off one line, or not joined by element edges.
std::vector<int> EdgeLine(const Mesh& mesh, std::vector<int> nodes, Eigen::Vector3d& axis) {
  if (nodes.size() < 2) return {};
  auto at = [&](int n) -> Eigen::Vector3d { return mesh.positions.row(n).transpose(); };
  // The two nodes farthest apart span the line.
  int first = nodes[0], last = nodes[0];
  double longest = -1;
  for (int a : nodes)
    for (int b : nodes)
      if (const double d = (at(b) - at(a)).norm(); d > longest) {
        longest = d;
        first = a;
        last = b;
      }
  axis = (at(last) - at(first)).normalized();
  for (int n : nodes) {
    const Eigen::Vector3d r = at(n) - at(first);
    if ((r - r.dot(axis) * axis).norm() > 1e-6 * longest) return {};
  }
  std::sort(nodes.begin(), nodes.end(), [&](int a, int b) {
    return (at(a) - at(first)).dot(axis) < (at(b) - at(first)).dot(axis);
  });
  for (size_t i = 0; i + 1 < nodes.size(); ++i)
    if (!AreEdgeNeighbours(mesh, nodes[i], nodes[i + 1])) return {};
  return nodes;
}

}  // namespace

NodalLoad MakeNodalLoad(const Mesh& mesh,
                        const ShellState& reference,
                        std::string name,
                        std::vector<int> nodes,
                        const Eigen::Vector3d& force,
                        const Eigen::Vector3d& moment) {
  const double share = 1.0 / static_cast<double>(nodes.size());
  NodalLoad load{std::move(name), nodes, share * force, share * moment, {}};
  Eigen::Vector3d axis;
  const std::vector<int> line =
      moment.isZero(0.0) ? std::vector<int>{} : EdgeLine(mesh, nodes, axis);
  if (line.empty()) return load;
  const double about_axis = moment.dot(axis);
  load.moment_per_node = share * (moment - about_axis * axis);
  const double per_segment = about_axis / static_cast<double>(line.size() - 1);
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    EdgeMomentSegment s;
    s.nodes[0] = line[i];
    s.nodes[1] = line[i + 1];
    s.reference.axis = axis;
    for (int k = 0; k < 2; ++k) s.reference.directors[k] = reference.Director(s.nodes[k]);
    s.moment = per_segment;
    load.edge_segments.push_back(s);
  }
  return load;
}

std::vector<EdgeMomentTerm> EdgeMomentTerms(const ShellModel& model, const ShellState& state) {
  std::vector<EdgeMomentTerm> terms;
  for (const auto& load : model.loads)
    for (const auto& s : load.edge_segments) {
      const int a = s.nodes[0], b = s.nodes[1];
      const EdgeTwist twist = EvaluateEdgeTwist(s.reference,
                                                state.positions.row(a).transpose(),
                                                state.positions.row(b).transpose(),
                                                state.rotations[a],
                                                state.rotations[b]);
      EdgeMomentTerm t;
      t.nodes[0] = a;
      t.nodes[1] = b;
      t.energy = -s.moment * twist.angle;
      t.force = -s.moment * twist.gradient;
      t.stiffness = -s.moment * twist.hessian;
      terms.push_back(t);
    }
  return terms;
}

Eigen::VectorXd EdgeMomentForce(const ShellModel& model, const ShellState& state) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
  for (const auto& t : EdgeMomentTerms(model, state))
    for (int k = 0; k < 2; ++k)
      f.segment<5>(kDofsPerNode * t.nodes[k]) -= t.force.segment<5>(5 * k);
  return f;
}

bool HasEdgeMoments(const ShellModel& model) {
  return std::any_of(model.loads.begin(), model.loads.end(), [](const NodalLoad& l) {
    return !l.edge_segments.empty();
  });
}

}  // namespace drape
