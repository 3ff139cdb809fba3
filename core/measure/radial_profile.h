// The outline of a shadow as a drapemeter's trace reads it: the radius of
// its farthest edge along rays from the centre, at evenly spaced angles.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/measure/shadow.h"

namespace drape {

struct RadialProfile {
  std::vector<double> angle;   // [rad], k · 2π/n from the plane's u axis, counter-clockwise
  std::vector<double> radius;  // [m], 0 where the ray meets no edge
};

// Along each of `samples` rays from `centre`, the farthest point where the
// ray crosses one of the shadow's edges: the outline's outermost radius,
// exact for the polygon (a hole or a fold inside the shadow does not count).
RadialProfile ShadowProfile(const Shadow& shadow, const Eigen::Vector2d& centre, int samples);

}  // namespace drape
