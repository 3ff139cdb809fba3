// Whether a scene's stages can be solved as posed, checked before any work:
// every node held by one thing at a time, and no gripper driven into an
// obstacle.
#pragma once

#include <string>
#include <vector>

#include "core/contact/node_contact.h"
#include "core/fe/shell_model.h"
#include "core/fe/stage_loading.h"
#include "core/model/scene.h"

namespace drape {

// A node can be held by one thing at a time: a support, or a gripper. Two
// holders of one node are fine while neither moves; a moving gripper must own
// its nodes alone, or the node would have to be in two places. Throws
// SceneError naming the stage's move.
void CheckHoldsDoNotConflict(const Scene& scene, const ShellModel& model);

// Why stage `index`'s motion puts a held node deeper than the thickness into
// an obstacle, naming the gripper, the obstacle and the key ("" when it does
// not): no equilibrium exists there, and the path would only find that out
// after many cut-backs. `released` marks the grippers let go.
std::string GripperDrivenIntoObstacle(const Scene& scene,
                                      int index,
                                      const ShellModel& model,
                                      const std::vector<bool>& released,
                                      const NodeContact& contact,
                                      const StageLoading& loading,
                                      const ShellState& state);

}  // namespace drape
