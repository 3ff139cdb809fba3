// A plan (docs/plan.md): a scene, the keys of its gripper paths that may
// change within bounds, what a good fold is (the objective), what no fold
// may do (the constraints) and how the optimiser searches. `drape plan`
// reads it, and every evaluation is the scene with the keys set.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/model/scene.h"
#include "core/model/units.h"

namespace drape {

// One varied scene key (docs/format.md §7), as a number in SI units (a
// length in m, an angle key such as `angle_deg` in its own plain number).
struct PlanParameter {
  std::string key;
  double min = 0, max = 0;
  double start = 0;  // the plan's `start`, else the scene's own value
  Dimension dimension;
  std::string unit;  // the unit `min` was written in, for reports ("cm")
};

// A probe's final position should be `target` [m].
struct ProbeTarget {
  std::string probe;
  Vec3 target{0, 0, 0};
  double weight = 1;
};

// A region of the fabric should lie flat on an obstacle: every node's
// distance from it within the thickness of `layer` layers
// ((layer − ½) h to the mid-surface). The term is the gap beyond that
// which `share` of the region's nodes stay within (1: the largest) [m].
// The nodes on one side of a line in the reference plane, the line's own
// included: a half folded over a diagonal, which no selection rule picks.
struct SideOfLine {
  Vec2 from{0, 0}, to{0, 0};  // the line [m]
  Vec2 toward{0, 0};          // a point on the side wanted [m]
};

struct FlatTerm {
  std::optional<Selection> select;  // one of select and side
  std::optional<SideOfLine> side;
  std::string on;  // an obstacle's name
  int layer = 1;
  double share = 1;
  double weight = 1;
};

struct PlanObjective {
  std::vector<ProbeTarget> probes;
  std::optional<FlatTerm> flat;
  double path_length_weight = 0;  // × the grippers' path length [m]
};

// What no evaluation may do at any step (docs/plan.md "Constraints").
struct PlanConstraints {
  bool stable = true;                       // 0 negative pivots at every step
  bool layers = true;                       // layers never nearer than the thickness
  bool grippers_outside = true;             // no held node inside an obstacle
  std::optional<double> max_gripper_force;  // [N], each gripper at each step
  std::optional<std::string> no_slip;       // an obstacle: no node slides on it
};

enum class PlanAlgorithm { kBobyqa, kCobyla };

struct PlanSearch {
  PlanAlgorithm algorithm = PlanAlgorithm::kCobyla;
  int max_evaluations = 60;
  // Stop when a step changes the objective by less than this [m].
  double tolerance = 1e-4;
};

struct Plan {
  std::filesystem::path file;        // absolute
  std::filesystem::path scene_file;  // absolute
  std::string scene_text;            // the scene file as read
  Scene scene;                       // the scene as read (the start's values)
  std::vector<PlanParameter> parameters;
  PlanObjective objective;
  PlanConstraints constraints;
  PlanSearch search;
  std::optional<double> time_limit_s;  // per evaluation (drape run --time-limit)
};

// Reads and checks a plan file: its scene, each key's value at the start
// and at both bounds (each read by the scene reader), the probes and
// obstacles it names. Throws SceneError naming the plan's key.
Plan ReadPlan(const std::filesystem::path& file);

// The scene of one evaluation as JSON text: the plan's scene with each
// parameter set to `x` (in the parameters' order), every relative `file`
// made absolute. Throws SceneError naming the key when the scene refuses it.
std::string PlanSceneText(const Plan& plan, const std::vector<double>& x);

// The starting point, in the parameters' order.
std::vector<double> StartOf(const Plan& plan);

// "stages[1].moves[0].path.arc.center[0] = 2.1 cm" for each parameter.
std::string DescribePoint(const Plan& plan, const std::vector<double>& x);

}  // namespace drape
