// Moments about a loaded edge as potentials: a load's moment about the line
// its nodes form does work −M θ through the edge's twist θ (edge_twist.h),
// with the load stiffness that work implies. Any other moment, and any moment
// on nodes that are not one line of element edges, stays a fixed vector on
// each node's rotation (stage_loading.h).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/fe/shell_model.h"

namespace drape {

// The load `force` and `moment` (totals) shared over `nodes`, the moment's
// part about the nodes' line (if they are one line of element edges, in
// order, at least two) as edge segments.
NodalLoad MakeNodalLoad(const Mesh& mesh,
                        const ShellState& reference,
                        std::string name,
                        std::vector<int> nodes,
                        const Eigen::Vector3d& force,
                        const Eigen::Vector3d& moment);

// One segment's work and its derivatives at unit load factor: energy −M θ,
// force −M ∂θ/∂q and stiffness −M ∂²θ/∂q² over its two nodes' DOFs.
struct EdgeMomentTerm {
  int nodes[2] = {0, 0};
  double energy = 0;  // [J]
  Eigen::Matrix<double, 10, 1> force;
  Eigen::Matrix<double, 10, 10> stiffness;
};

std::vector<EdgeMomentTerm> EdgeMomentTerms(const ShellModel& model, const ShellState& state);

// Σ M ∂θ/∂q over every edge segment (full, 5 per node): the external force of
// the edge moments at unit load factor.
Eigen::VectorXd EdgeMomentForce(const ShellModel& model, const ShellState& state);

bool HasEdgeMoments(const ShellModel& model);

}  // namespace drape
