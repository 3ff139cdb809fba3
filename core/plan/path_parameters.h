// The numbers of a scene's paths a plan can vary (docs/plan.md): each
// move's line offset, arc centre and angle, keyframe offsets — the keys
// the workbench's path handles edit — with their scene key, a name a
// person reads and the value the scene holds.
#pragma once

#include <string>
#include <vector>

#include "core/model/scene.h"
#include "core/model/units.h"

namespace drape {

struct PathParameter {
  std::string key;    // "stages[1].moves[0].path.arc.center[0]"
  std::string label;  // "R: end, arc centre x"
  double value = 0;   // SI (an angle key: degrees, as the key takes it)
  Dimension dimension;
};

// In the order of the stages, their moves and the paths' numbers.
std::vector<PathParameter> PathParameters(const Scene& scene);

}  // namespace drape
