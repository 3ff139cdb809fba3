// The rotation of a loaded edge about its own axis: what a moment about that
// axis does work through.
//
// A moment vector fixed in space is not conservative once the edge it loads
// turns out of the moment's plane, and it has no load stiffness; a rolled-up
// strip's tangent then turns indefinite where the strip is stable. The twist
// angle below is a function of the configuration, so −M θ is a potential: the
// moment's work is exact for any rotation, and its Hessian is the load
// stiffness.
//
// A segment of the edge joins two nodes. Its axis is the unit chord a between
// them; the swing S is the smallest rotation taking the reference axis a₀ to
// a. Each node's twist is the angle, about a, from its reference director
// (projected normal to a₀) carried by S, to its current director; the
// segment's twist is the mean of its two nodes'. For an edge that stays on its
// axis (a = a₀) the twist is the rotation of the directors about it. The
// swing is undefined for an edge turned end for end (a = −a₀): the values are
// then not finite, and the steps that reach it are cut back.
#pragma once

#include <Eigen/Core>

namespace drape {

// A segment's reference: its unit axis a₀ and each node's reference director.
struct EdgeTwistReference {
  Eigen::Vector3d axis;
  Eigen::Vector3d directors[2];
};

// The twist θ and its first and second derivatives with respect to the two
// nodes' DOFs (per node: Δu (3), then the rotation increment (a, b) in its
// tangent basis, director.h), at zero increment.
struct EdgeTwist {
  double angle = 0;  // [rad], in (−π, π]
  Eigen::Matrix<double, 10, 1> gradient;
  Eigen::Matrix<double, 10, 10> hessian;
};

// The segment's twist at positions x₀, x₁ and orientations Λ₀, Λ₁.
EdgeTwist EvaluateEdgeTwist(const EdgeTwistReference& reference,
                            const Eigen::Vector3d& x0,
                            const Eigen::Vector3d& x1,
                            const Eigen::Matrix3d& rotation0,
                            const Eigen::Matrix3d& rotation1);

}  // namespace drape
