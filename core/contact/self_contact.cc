#include "core/contact/self_contact.h"

#include <algorithm>
#include <cmath>

#include "core/contact/additive_ccd.h"
#include "core/contact/contact_barrier.h"
#include "core/geometry/primitive_distance.h"

namespace drape {
namespace {

Eigen::Vector3d Row(const Positions& x, int i) {
  return x.row(i).transpose();
}

}  // namespace

SelfContact::SelfContact(const Mesh& mesh, const SelfContactSettings& settings)
    : settings_(settings),
      list_margin_(std::max(2 * (settings.offset + settings.activation), MeanEdgeLength(mesh))),
      proximity_(mesh, settings.exclusion),
      rest_(mesh.positions) {}

bool SelfContact::ListCovers(const Positions& x, double motion) const {
  // A pair outside the list was farther than reach + margin apart where the
  // list was made; its distance shrinks by at most twice the spread of the
  // nodes' motions since (a translation of the whole fabric moves no pair
  // closer).
  if (list_positions_.rows() != x.rows()) return false;
  return 2 * (MotionSpread(x - list_positions_) + motion) <= list_margin_;
}

SelfContactEvaluation SelfContact::Evaluate(const Positions& x, bool with_hessian) {
  SelfContactEvaluation out;
  out.gradient = Eigen::VectorXd::Zero(3 * x.rows());
  if (!ListCovers(x, 0)) {
    list_ = proximity_.Candidates(x, settings_.offset + settings_.activation + list_margin_);
    list_positions_ = x;
  }
  const ProximityPairs& pairs = list_;
  // `side`: how many of the four nodes (the first) make one side of the pair.
  auto add = [&](const std::array<int, 4>& nodes,
                 int side,
                 const DistanceDerivatives& d,
                 const PairPotential& p) {
    out.smallest_distance = std::min(out.smallest_distance, std::sqrt(d.squared));
    if (p.energy == 0) return;
    ++out.active_pairs;
    out.energy += p.energy;
    Eigen::Vector3d on_side = Eigen::Vector3d::Zero();
    for (int k = 0; k < side; ++k) on_side += p.gradient.segment<3>(3 * k);
    out.force += on_side.norm();
    for (int k = 0; k < 4; ++k)
      out.gradient.segment<3>(3 * nodes[k]) += p.gradient.segment<3>(3 * k);
    if (with_hessian) {
      out.block_nodes.push_back(nodes);
      out.blocks.push_back(p.hessian);
    }
  };
  // The list reaches farther than the barrier: its other pairs cost only
  // their distance.
  const double reach = settings_.offset + settings_.activation;
  const auto& triangles = proximity_.triangles();
  for (const auto& [i, t] : pairs.point_triangle) {
    const auto& tri = triangles[t];
    if (PointTriangle(Row(x, i), Row(x, tri[0]), Row(x, tri[1]), Row(x, tri[2])).squared >=
        reach * reach)
      continue;
    const DistanceDerivatives d =
        PointTriangleDerivatives(Row(x, i), Row(x, tri[0]), Row(x, tri[1]), Row(x, tri[2]));
    add({i, tri[0], tri[1], tri[2]},
        1,
        d,
        BarrierPotential(d, settings_.offset, settings_.activation, settings_.stiffness));
  }
  const auto& edges = proximity_.edges();
  for (const auto& [a, b] : pairs.edge_edge) {
    const auto& p = edges[a];
    const auto& q = edges[b];
    const Eigen::Vector3d a0 = Row(x, p[0]), a1 = Row(x, p[1]), b0 = Row(x, q[0]),
                          b1 = Row(x, q[1]);
    if (EdgeEdge(a0, a1, b0, b1).squared >= reach * reach) continue;
    const DistanceDerivatives d = EdgeEdgeDerivatives(a0, a1, b0, b1);
    const double threshold =
        MollifierThreshold(Row(rest_, p[0]), Row(rest_, p[1]), Row(rest_, q[0]), Row(rest_, q[1]));
    add({p[0], p[1], q[0], q[1]},
        2,
        d,
        MollifiedEdgeEdgePotential(d,
                                   a0,
                                   a1,
                                   b0,
                                   b1,
                                   threshold,
                                   settings_.offset,
                                   settings_.activation,
                                   settings_.stiffness));
  }
  return out;
}

std::vector<std::pair<int, int>> SelfContact::NodePairs(const Positions& x, double reach) const {
  const ProximityPairs pairs = proximity_.Candidates(x, reach);
  std::vector<std::pair<int, int>> out;
  auto add = [&](const std::array<int, 4>& n) {
    for (int k = 0; k < 4; ++k)
      for (int l = k + 1; l < 4; ++l)
        if (n[k] != n[l]) out.emplace_back(std::min(n[k], n[l]), std::max(n[k], n[l]));
  };
  for (const auto& [i, t] : pairs.point_triangle) {
    const auto& tri = proximity_.triangles()[t];
    add({i, tri[0], tri[1], tri[2]});
  }
  for (const auto& [a, b] : pairs.edge_edge) {
    const auto &p = proximity_.edges()[a], &q = proximity_.edges()[b];
    add({p[0], p[1], q[0], q[1]});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double SelfContact::StepBound(const Positions& x, const Positions& dx) const {
  // Every pair that could come within the offset during the step: the
  // list's, or those whose boxes swept along the step come that close.
  const ProximityPairs pairs =
      ListCovers(x, MotionSpread(dx)) ? list_ : proximity_.SweptCandidates(x, dx, settings_.offset);
  AccdSettings accd;
  accd.offset = settings_.offset;
  double t = 1;
  // Each pair need only advance as far as the least bound so far.
  const auto& triangles = proximity_.triangles();
  for (const auto& [i, k] : pairs.point_triangle) {
    if (t == 0) return 0;
    accd.max_t = t;
    const auto& tri = triangles[k];
    t = std::min(t,
                 PointTriangleStepBound(Row(x, i),
                                        Row(x, tri[0]),
                                        Row(x, tri[1]),
                                        Row(x, tri[2]),
                                        Row(dx, i),
                                        Row(dx, tri[0]),
                                        Row(dx, tri[1]),
                                        Row(dx, tri[2]),
                                        accd));
  }
  const auto& edges = proximity_.edges();
  for (const auto& [a, b] : pairs.edge_edge) {
    if (t == 0) return 0;
    accd.max_t = t;
    const auto& p = edges[a];
    const auto& q = edges[b];
    t = std::min(t,
                 EdgeEdgeStepBound(Row(x, p[0]),
                                   Row(x, p[1]),
                                   Row(x, q[0]),
                                   Row(x, q[1]),
                                   Row(dx, p[0]),
                                   Row(dx, p[1]),
                                   Row(dx, q[0]),
                                   Row(dx, q[1]),
                                   accd));
  }
  return t;
}

}  // namespace drape
