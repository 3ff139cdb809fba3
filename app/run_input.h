// What the rendering and export commands read: a result folder (every
// converged state) or a scene (its reference state only), as one model and
// a list of states, state 0 being the reference.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/model/scene.h"

namespace drape::app {

struct RunInput {
  Scene scene;
  ShellModel model;
  std::vector<ShellState> states;              // [0]: reference, then step 1, 2, …
  std::vector<std::string> stage_names;        // per state ("" for the reference)
  std::vector<int> stages;                     // per state, index in scene.stages (−1: reference)
  std::vector<double> lambdas;                 // per state
  std::vector<double> final_contact_pressure;  // per node at the last state, or empty
  std::vector<double> final_friction_state;    // the same: 0 none, 1 sticking, 2 sliding
  bool is_result = false;
};

// True when `input` is a result folder or a result.json (a "drape_result"
// document), false for anything else (a scene); throws std::runtime_error
// when it cannot be opened.
bool IsResultInput(const std::filesystem::path& input);

// Throws std::runtime_error (or SceneError) with one message naming the
// file and the problem.
RunInput ReadRunInput(const std::filesystem::path& input);

// The index into `states` of "--step" (a step number, 0 for the reference,
// or "last"); throws std::invalid_argument naming the valid range.
size_t StepIndex(const RunInput& run, const std::string& step);

// "1280x720" → {1280, 720}; throws std::invalid_argument.
std::pair<int, int> ParseSize(const std::string& size);

}  // namespace drape::app
