// What a plan's measures and the trajectory export both ask of a gripper:
// until which stage it holds, and where its held nodes are.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/model/scene.h"

namespace drape {

// The first stage that releases `gripper` (it holds before it); INT_MAX
// when none does.
int ReleaseStage(const Scene& scene, const std::string& gripper);

// The mean of `x`'s rows `nodes` (the origin for none).
Eigen::Vector3d Centroid(const Eigen::Matrix<double, Eigen::Dynamic, 3>& x,
                         const std::vector<int>& nodes);

}  // namespace drape
