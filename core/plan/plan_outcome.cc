#include "core/plan/plan_outcome.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "core/io/result_reader.h"
#include "core/model/node_selection.h"
#include "core/model/obstacle_geometry.h"
#include "core/model/outline_geometry.h"
#include "core/plan/held_nodes.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The smallest value over the steps and where it was.
struct Worst {
  double value = kInf;
  int step = 0;
  void Take(double v, int at) {
    if (v < value) value = v, step = at;
  }
};

size_t ObstacleIndex(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    if (scene.obstacles[i].name == name) return i;
  return scene.obstacles.size();
}

ObstaclePlacement PlacementAt(const RunRecord& record, size_t step, size_t obstacle) {
  if (step < record.steps.size() && obstacle < record.steps[step].obstacles.size())
    return record.steps[step].obstacles[obstacle];
  return {};
}

// The signed distance of the held nodes from every obstacle, the path each
// gripper's nodes travel while held, and the largest force it carries.
void MeasureGrippers(const Plan& plan,
                     const RunRecord& record,
                     const std::vector<std::unique_ptr<ObstacleGeometry>>& obstacles,
                     Worst& outside,
                     Worst& force,
                     double& path_length) {
  const Scene& scene = record.scene;
  path_length = 0;
  for (const Gripper& gripper : scene.grippers) {
    const std::vector<int> nodes = SelectNodesInParts(gripper.select, scene, record.mesh);
    const int released = ReleaseStage(scene, gripper.name);
    std::optional<Eigen::Vector3d> last;
    for (size_t i = 0; i < record.states.size(); ++i) {
      const StoredStep& state = record.states[i];
      if (state.stage >= released) break;
      const Eigen::Vector3d at = Centroid(state.positions, nodes);
      if (last) path_length += (at - *last).norm();
      last = at;
      for (size_t o = 0; o < obstacles.size(); ++o) {
        const ObstaclePlacement place = PlacementAt(record, i, o);
        for (int n : nodes)
          outside.Take(
              obstacles[o]->Query(place.ToScene(state.positions.row(n).transpose())).distance,
              state.step);
      }
      if (plan.constraints.max_gripper_force && i < record.steps.size())
        for (const NamedVector& r : record.steps[i].reactions)
          if (r.name == gripper.name)
            force.Take(*plan.constraints.max_gripper_force - r.value.norm(), state.step);
    }
  }
}

// In the reference x and y (an elevated fabric keeps them). A node on the
// line, to round-off, belongs to the side.
std::vector<int> NodesOnSide(const SideOfLine& side, const Mesh& mesh) {
  const Eigen::Vector2d a(side.from[0], side.from[1]), b(side.to[0], side.to[1]),
      t(side.toward[0], side.toward[1]);
  auto cross = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d u = b - a, v = p - a;
    return u.x() * v.y() - u.y() * v.x();
  };
  const double sign = cross(t) > 0 ? 1 : -1, slack = 1e-9 * (b - a).squaredNorm();
  std::vector<int> nodes;
  for (int n = 0; n < mesh.NodeCount(); ++n)
    if (sign * cross(Eigen::Vector2d(mesh.positions(n, 0), mesh.positions(n, 1))) >= -slack)
      nodes.push_back(n);
  return nodes;
}

// The gap beyond the layers' thickness that `share` of the region stays within.
double FlatGap(const Plan& plan,
               const RunRecord& record,
               const std::vector<std::unique_ptr<ObstacleGeometry>>& obstacles) {
  const FlatTerm& flat = *plan.objective.flat;
  const std::vector<int> nodes = flat.select
                                     ? SelectNodesInParts(*flat.select, record.scene, record.mesh)
                                     : NodesOnSide(*flat.side, record.mesh);
  const size_t o = ObstacleIndex(record.scene, flat.on);
  const size_t last = record.states.size() - 1;
  const ObstaclePlacement place = PlacementAt(record, last, o);
  const double rest = (flat.layer - 0.5) * record.scene.material.thickness;
  std::vector<double> gaps;
  for (int n : nodes) {
    const Eigen::Vector3d x = record.states[last].positions.row(n).transpose();
    gaps.push_back(std::max(0.0, obstacles[o]->Query(place.ToScene(x)).distance - rest));
  }
  if (gaps.empty()) return 0;
  std::sort(gaps.begin(), gaps.end());
  const size_t k = static_cast<size_t>(std::ceil(flat.share * gaps.size()));
  return gaps[std::clamp<size_t>(k, 1, gaps.size()) - 1];
}

// Pivots, layers and slip, as result.json reports each step.
void MeasureSteps(const json& steps, Worst& pivots, Worst& layers, Worst& slip) {
  for (const json& s : steps) {
    const int step = s.value("step", 0);
    pivots.Take(-s.value("negative_pivots", 0), step);
    if (s.contains("layers") && s["layers"].contains("min_distance"))
      layers.Take(s["layers"]["min_distance"].get<double>(), step);
    if (s.contains("contact") && s["contact"].contains("friction"))
      slip.Take(-s["contact"]["friction"].value("sliding", 0), step);
  }
}

}  // namespace

double ConstraintMargin::Violation() const {
  return std::max(0.0, Value());
}

double ConstraintMargin::Value() const {
  return std::isinf(margin) && margin > 0 ? -1.0 : -margin / scale;
}

bool EvaluationOutcome::Feasible() const {
  return Converged() && std::all_of(constraints.begin(), constraints.end(), [](const auto& c) {
           return c.Violation() == 0;
         });
}

double PlanScale(const Plan& plan) {
  double diagonal = 0;
  for (const Fabric* part : FabricParts(plan.scene)) {
    const Bounds2 b = OutlineBounds(part->outline);
    diagonal = std::max(diagonal, std::hypot(b.max[0] - b.min[0], b.max[1] - b.min[1]));
  }
  return diagonal > 0 ? diagonal : 1.0;
}

double PenalisedValue(const EvaluationOutcome& outcome,
                      double scale,
                      std::optional<double> worst_feasible) {
  double violation = 0;
  for (const ConstraintMargin& c : outcome.constraints) violation += c.Violation();
  if (outcome.Converged() && violation == 0) return *outcome.objective;
  const double unfinished = 1 - std::clamp(outcome.progress, 0.0, 1.0);
  if (!outcome.Converged()) violation += 2 * unfinished;
  if (worst_feasible) {
    const double own = outcome.Converged() ? *outcome.objective : 0.0;
    return std::max(*worst_feasible, own) + 0.1 * scale * (1 + violation);
  }
  if (!outcome.Converged()) return scale * (2 + 8 * unfinished);
  return *outcome.objective + scale * (1 + violation);
}

EvaluationOutcome MeasureEvaluation(const Plan& plan, const fs::path& result_dir) {
  EvaluationOutcome out;
  const fs::path file = result_dir / "result.json";
  if (!fs::exists(file)) return out;
  json result;
  try {
    std::ifstream in(file);
    result = json::parse(in);
    out.status = result.value("status", "unreadable");
    out.message = result.value("message", "");
    if (result.contains("timing")) out.wall_s = result["timing"].value("total_s", 0.0);
    double reached = 0;
    for (const json& stage : result.value("stages", json::array()))
      reached += std::clamp(stage.value("final_lambda", 0.0), 0.0, 1.0);
    const size_t stages = plan.scene.stages.size();
    out.progress = stages ? std::min(1.0, reached / stages) : 0.0;
  } catch (const std::exception& e) {
    out.status = "unreadable";
    out.message = e.what();
    return out;
  }
  try {
    const RunRecord record = ReadRunRecord(result_dir);
    if (record.states.empty()) return out;
    const fs::path scene_dir = plan.scene_file.parent_path();
    std::vector<std::unique_ptr<ObstacleGeometry>> obstacles;
    for (size_t o = 0; o < record.scene.obstacles.size(); ++o)
      obstacles.push_back(MakeObstacleGeometry(
          record.scene.obstacles[o], scene_dir, "obstacles[" + std::to_string(o) + "]"));

    Worst pivots, layers, slip, outside, force;
    MeasureSteps(result.value("steps", json::array()), pivots, layers, slip);
    double path_length = 0;
    MeasureGrippers(plan, record, obstacles, outside, force, path_length);

    const PlanConstraints& k = plan.constraints;
    const Scene& scene = record.scene;
    const double h = scene.material.thickness;
    if (k.stable) {
      const double margin = pivots.value == kInf ? 0 : pivots.value;
      out.constraints.push_back({"stable", margin, "pivots", 1.0, pivots.step});
    }
    if (k.layers) {
      const double offset =
          scene.contact && scene.contact->thickness ? *scene.contact->thickness : h;
      const double margin = layers.value == kInf ? kInf : layers.value - offset;
      out.constraints.push_back({"layers", margin, "m", offset, layers.step});
    }
    if (k.grippers_outside)
      out.constraints.push_back({"grippers_outside", outside.value, "m", h, outside.step});
    if (k.max_gripper_force)
      out.constraints.push_back(
          {"max_gripper_force", force.value, "N", *k.max_gripper_force, force.step});
    if (k.no_slip) {
      const double margin = slip.value == kInf ? 0 : slip.value;
      out.constraints.push_back({"no_slip", margin, "nodes", 1.0, slip.step});
    }
    if (out.status != "converged") return out;

    double objective = 0;
    const json& probes = result.at("final").at("probes");
    for (const ProbeTarget& t : plan.objective.probes) {
      const json& p = probes.at(t.probe);
      const Eigen::Vector3d at(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
      const double d = (at - Eigen::Vector3d(t.target[0], t.target[1], t.target[2])).norm();
      out.probe_distances.push_back(d);
      objective += t.weight * d;
    }
    if (plan.objective.flat) {
      out.flat_gap = FlatGap(plan, record, obstacles);
      objective += plan.objective.flat->weight * *out.flat_gap;
    }
    out.path_length = path_length;
    objective += plan.objective.path_length_weight * path_length;
    if (std::isfinite(objective)) out.objective = objective;
  } catch (const std::exception& e) {
    out.status = "unreadable";
    out.message = e.what();
  }
  return out;
}

}  // namespace drape
