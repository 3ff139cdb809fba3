#include "core/io/result_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "core/io/result_writer.h"
#include "core/io/scene_reader.h"
#include "core/mechanics/director.h"
#include "core/model/scene_error.h"

namespace drape {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void Fail(const fs::path& file, const std::string& message) {
  throw std::runtime_error(file.string() + ": " + message);
}

// get<int>() casts a float such as 1e10 to int: undefined behaviour, which
// GCC's sanitizers do not report, and a step number made up.
int IntOf(const json& j, const std::string& where, const fs::path& file) {
  const bool fits = j.is_number_unsigned() ? j.get<std::uint64_t>() <= INT_MAX
                    : j.is_number_integer()
                        ? j.get<std::int64_t>() >= INT_MIN && j.get<std::int64_t>() <= INT_MAX
                        : false;
  if (!fits) Fail(file, where + ": " + j.dump() + " is not an integer in the range of int");
  return j.get<int>();
}

ObstaclePlacement PlacementOf(const json& j) {
  ObstaclePlacement p;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p.rotation(r, c) = j.at("rotation").at(r).at(c).get<double>();
    p.translation(r) = j.at("translation").at(r).get<double>();
  }
  return p;
}

// steps[i].reactions: {name: [Fx, Fy, Fz]}, in the order the solver writes
// them (supports, then grippers); result.json's own order is lost to
// nlohmann::json's sorted objects.
std::vector<NamedVector> ReactionsOf(const json& j,
                                     const Scene& scene,
                                     const std::string& where,
                                     const fs::path& file) {
  if (!j.is_object()) Fail(file, where + ": " + j.dump() + " is not an object of forces");
  std::vector<std::string> order;
  for (const auto& s : scene.supports) order.push_back(s.name);
  for (const auto& g : scene.grippers) order.push_back(g.name);
  auto rank = [&](const std::string& name) {
    return std::find(order.begin(), order.end(), name) - order.begin();
  };
  std::vector<NamedVector> reactions;
  for (const auto& [name, force] : j.items()) {
    NamedVector r{name, Eigen::Vector3d::Zero()};
    bool ok = force.is_array() && force.size() == 3;
    for (int c = 0; ok && c < 3; ++c) {
      ok = force[c].is_number() && std::isfinite(force[c].get<double>());
      if (ok) r.value(c) = force[c].get<double>();
    }
    if (!ok)
      Fail(file, where + "." + name + ": " + force.dump() + " is not a force [Fx, Fy, Fz] in N");
    reactions.push_back(std::move(r));
  }
  std::stable_sort(reactions.begin(), reactions.end(), [&](const auto& a, const auto& b) {
    return rank(a.name) < rank(b.name);
  });
  return reactions;
}

// The parts of a fabric of several (`mesh.parts`; states.bin keeps nodes and
// quads only): consecutive ranges covering the mesh, one per part.
std::vector<MeshPart> PartsOf(const json& r,
                              const Mesh& mesh,
                              const Scene& scene,
                              const fs::path& file) {
  if (scene.other_parts.empty()) return {};
  const json* parts = r.contains("mesh") ? &r["mesh"] : nullptr;
  if (!parts || !parts->contains("parts") || !(*parts)["parts"].is_array() ||
      (*parts)["parts"].size() != scene.other_parts.size() + 1)
    Fail(file, "mesh.parts: expected one entry per part of the scene's fabric");
  std::vector<MeshPart> out;
  int nodes = 0, elements = 0;
  for (const json& p : (*parts)["parts"]) {
    const std::string where = "mesh.parts[" + std::to_string(out.size()) + "]";
    MeshPart part{IntOf(p.at("first_node"), where + ".first_node", file),
                  IntOf(p.at("nodes"), where + ".nodes", file),
                  IntOf(p.at("first_element"), where + ".first_element", file),
                  IntOf(p.at("elements"), where + ".elements", file)};
    if (part.first_node != nodes || part.first_element != elements || part.nodes <= 0 ||
        part.elements <= 0)
      Fail(file, where + ": not the range after the part before it");
    nodes += part.nodes;
    elements += part.elements;
    out.push_back(part);
  }
  if (nodes != mesh.NodeCount() || elements != mesh.ElementCount())
    Fail(file, "mesh.parts: the parts do not cover the mesh of states.bin");
  return out;
}

}  // namespace

RunRecord ReadRunRecord(const fs::path& path) {
  std::error_code ec;
  const fs::path file = fs::is_directory(path, ec) ? path / kResultFileName : path;
  std::ifstream in(file);
  if (!in) Fail(file, "cannot open the result (expected a result folder or its result.json)");
  json r;
  try {
    r = json::parse(in);
  } catch (const json::exception& e) {
    Fail(file, std::string("not valid JSON: ") + e.what());
  }
  if (!r.is_object() || !r.contains("drape_result"))
    Fail(file, "not a Drape Studio result (no 'drape_result' key)");
  RunRecord record;
  record.directory = file.parent_path();
  try {
    record.status = r.value("status", "");
    record.message = r.value("message", "");
    record.scene = SceneFromJson(r.at("scene_resolved"), record.directory);
    const StateFile states =
        ReadStateFile(record.directory / r.value("states_file", kStatesFileName));
    record.mesh = states.mesh;
    record.mesh.parts = PartsOf(r, record.mesh, record.scene, file);
    record.states = states.steps;
    std::vector<std::string> obstacle_names;
    for (const auto& o : record.scene.obstacles) obstacle_names.push_back(o.name);
    for (const auto& s : r.at("steps")) {
      RecordedStep step;
      const std::string where = "steps[" + std::to_string(record.steps.size()) + "]";
      step.stage = IntOf(s.at("stage"), where + ".stage", file);
      step.step = IntOf(s.at("step"), where + ".step", file);
      step.lambda = s.at("lambda").get<double>();
      if (step.stage >= 0 && step.stage < static_cast<int>(record.scene.stages.size()))
        step.stage_name = record.scene.stages[step.stage].name;
      step.obstacles.assign(obstacle_names.size(), ObstaclePlacement{});
      if (s.contains("obstacles"))
        for (size_t o = 0; o < obstacle_names.size(); ++o)
          if (s["obstacles"].contains(obstacle_names[o]))
            step.obstacles[o] = PlacementOf(s["obstacles"][obstacle_names[o]]);
      if (s.contains("reactions"))
        step.reactions = ReactionsOf(s["reactions"], record.scene, where + ".reactions", file);
      record.steps.push_back(std::move(step));
    }
    if (r.contains("final") && r["final"].contains("contact_pressure"))
      record.final_contact_pressure = r["final"]["contact_pressure"].get<std::vector<double>>();
    if (r.contains("final") && r["final"].contains("friction_state"))
      record.final_friction_state = r["final"]["friction_state"].get<std::vector<double>>();
  } catch (const SceneError& e) {
    Fail(file, std::string("scene_resolved: ") + e.what());
  } catch (const json::exception& e) {
    Fail(file, std::string("malformed result: ") + e.what());
  }
  // A run still going, or killed, has states.bin ahead of result.json (which
  // it rewrites about once a second). The states carry their stage, step
  // and λ; only moved obstacles' placements are result.json's alone, so
  // without moving obstacles every state counts.
  bool obstacles_move = false;
  for (const auto& stage : record.scene.stages)
    for (const auto& move : stage.moves) obstacles_move |= !move.obstacle.empty();
  if (!obstacles_move)
    for (size_t i = record.steps.size(); i < record.states.size(); ++i) {
      RecordedStep step;
      step.stage = record.states[i].stage;
      step.step = record.states[i].step;
      step.lambda = record.states[i].lambda;
      if (step.stage >= 0 && step.stage < static_cast<int>(record.scene.stages.size()))
        step.stage_name = record.scene.stages[step.stage].name;
      step.obstacles.assign(record.scene.obstacles.size(), ObstaclePlacement{});
      record.steps.push_back(std::move(step));
    }
  // Otherwise keep the steps both have (a run cut short may also have one
  // state fewer than result.json lists).
  const size_t n = std::min(record.states.size(), record.steps.size());
  record.states.resize(n);
  record.steps.resize(n);
  return record;
}

ShellState StateOf(const RunRecord& record, size_t i) {
  const StoredStep& s = record.states.at(i);
  ShellState state;
  state.positions = s.positions;
  state.rotations.resize(s.directors.rows());
  for (int n = 0; n < s.directors.rows(); ++n)
    state.rotations[n] = RotationFromDirector(s.directors.row(n).transpose());
  state.obstacles = record.steps.at(i).obstacles;
  return state;
}

}  // namespace drape
