#include "app/run_input.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

#include "core/io/result_reader.h"
#include "core/io/scene_reader.h"

namespace drape::app {
namespace fs = std::filesystem;

bool IsResultInput(const fs::path& input) {
  std::error_code ec;
  if (fs::is_directory(input, ec)) return true;
  std::ifstream in(input);
  if (!in) throw std::runtime_error(input.string() + ": cannot open");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    return j.is_object() && j.contains("drape_result");
  } catch (const nlohmann::json::exception&) {
    return false;  // the scene reader names the line
  }
}

RunInput ReadRunInput(const fs::path& input) {
  RunInput run;
  if (!IsResultInput(input)) {
    run.scene = ReadScene(input);
    run.model = BuildShellModel(run.scene);
    run.states.push_back(run.model.reference);
    run.states.back().obstacles.assign(run.scene.obstacles.size(), ObstaclePlacement{});
    run.stage_names.push_back("");
    run.stages.push_back(-1);
    run.lambdas.push_back(0);
    return run;
  }
  RunRecord record = ReadRunRecord(input);
  run.is_result = true;
  run.scene = record.scene;
  run.model = BuildShellModel(record.scene, record.mesh);
  run.states.push_back(run.model.reference);
  run.states.back().obstacles.assign(run.scene.obstacles.size(), ObstaclePlacement{});
  run.stage_names.push_back("");
  run.stages.push_back(-1);
  run.lambdas.push_back(0);
  for (size_t i = 0; i < record.states.size(); ++i) {
    if (record.states[i].positions.rows() != run.model.NodeCount())
      throw std::runtime_error(record.directory.string() +
                               ": the state file does not match the result's mesh");
    run.states.push_back(StateOf(record, i));
    run.stage_names.push_back(record.steps[i].stage_name);
    run.stages.push_back(record.steps[i].stage);
    run.lambdas.push_back(record.steps[i].lambda);
  }
  run.final_contact_pressure = record.final_contact_pressure;
  run.final_friction_state = record.final_friction_state;
  return run;
}

size_t StepIndex(const RunInput& run, const std::string& step) {
  const size_t last = run.states.size() - 1;
  if (step == "last") return last;
  size_t used = 0;
  int n = -1;
  try {
    n = std::stoi(step, &used);
  } catch (const std::exception&) {
  }
  if (used != step.size() || n < 0 || static_cast<size_t>(n) > last)
    throw std::invalid_argument("--step: '" + step + "' is not a step of this " +
                                (run.is_result ? "result" : "scene") +
                                "; give 0 (the reference state)" +
                                (last > 0 ? " to " + std::to_string(last) : "") + " or 'last'");
  return static_cast<size_t>(n);
}

std::pair<int, int> ParseSize(const std::string& size) {
  const auto x = size.find('x');
  size_t a = 0, b = 0;
  int w = 0, h = 0;
  try {
    w = std::stoi(size.substr(0, x), &a);
    h = std::stoi(size.substr(x + 1), &b);
  } catch (const std::exception&) {
  }
  if (x == std::string::npos || a != x || b != size.size() - x - 1 || w < 16 || h < 16 ||
      w > 8192 || h > 8192)
    throw std::invalid_argument("--size: '" + size +
                                "' is not WIDTHxHEIGHT in pixels (16 to 8192), e.g. 1280x720");
  return {w, h};
}

}  // namespace drape::app
