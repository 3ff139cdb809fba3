// A result folder read back (docs/format.md §5): the resolved scene, the mesh
// and every converged state, for rendering and export without re-solving.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/fe/shell_state.h"
#include "core/io/state_file.h"
#include "core/model/scene.h"
#include "core/solve/step_state.h"

namespace drape {

struct RecordedStep {
  int stage = 0;
  std::string stage_name;
  int step = 0;
  double lambda = 0;
  std::vector<ObstaclePlacement> obstacles;  // one per scene obstacle
  // `reactions`: the force each support and gripper exerts on the fabric
  // [N], supports then grippers in the scene's order (any other name after
  // them). Empty for a step only states.bin has.
  std::vector<NamedVector> reactions;
};

struct RunRecord {
  std::filesystem::path directory;
  Scene scene;  // `scene_resolved`
  std::string status, message;
  Mesh mesh;                                   // from states.bin
  std::vector<StoredStep> states;              // positions and directors per step
  std::vector<RecordedStep> steps;             // what result.json says of each
  std::vector<double> final_contact_pressure;  // per node, last step; empty without contact
  // Per node, last step: 0 no friction, 1 sticking, 2 sliding; empty
  // without friction.
  std::vector<double> final_friction_state;
};

// `path` is a result folder or its result.json. Throws std::runtime_error
// naming the file and the problem (missing, not a result, a step's stage or
// number that is not an integer, a state file that does not match the
// result's mesh or is damaged, see ReadStateFile; a reaction that is not
// three finite numbers).
RunRecord ReadRunRecord(const std::filesystem::path& path);

// The shell state of step index `i` (0-based in `states`): positions and
// nodal rotations rebuilt from the stored directors.
ShellState StateOf(const RunRecord& record, size_t i);

}  // namespace drape
