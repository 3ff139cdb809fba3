// The nodes of a drape: the folds that stand out of the shadow's outline,
// found as the maxima of its radius that are prominent enough.
#pragma once

#include <vector>

#include "core/measure/radial_profile.h"

namespace drape {

struct DrapeNode {
  double angle = 0;      // [rad], the profile's angle at the maximum
  double radius = 0;     // [m]
  double amplitude = 0;  // [m], its radius minus the mean of the minima on either side
};

// The maxima of the circular profile whose topographic prominence is at
// least `min_prominence` [m]: a maximum's prominence is its radius minus
// the higher of the lowest radii met walking each way round before a
// larger radius (or, from the largest, all the way round). Ripples of the
// outline smaller than `min_prominence` are not nodes. In the order of the
// angle; the minima on either side of a node are the lowest radii between
// it and the next node each way.
std::vector<DrapeNode> FindDrapeNodes(const RadialProfile& profile, double min_prominence);

}  // namespace drape
