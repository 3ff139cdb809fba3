// Writing a run: `result.json` (docs/format.md, "Result"), the binary state
// file `states.bin` and `steps.csv` (one row per step, for spreadsheets) beside
// it. The state file and the CSV are appended and flushed after every
// converged step, so a run that is cut off keeps every state reached;
// result.json is written when the run ends, however it ends.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"

namespace drape {

struct ErrorEstimate;

inline constexpr int kResultFormatVersion = 1;
inline constexpr char kStatesFileName[] = "states.bin";
inline constexpr char kResultFileName[] = "result.json";
inline constexpr char kStepsCsvFileName[] = "steps.csv";

class ResultWriter {
 public:
  // Creates `directory` (and parents) and starts states.bin with the mesh.
  // Throws std::runtime_error naming the path when it cannot.
  ResultWriter(const std::filesystem::path& directory, const Scene& scene, const ShellModel& model);
  ~ResultWriter();

  // Records one converged step (the observer the CLI installs): appended to
  // states.bin and steps.csv at once, and result.json (status "running")
  // rewritten after the first step and then at most about once a second.
  void AddStep(const StepState& step);

  // Writes result.json with the status of `summary`.
  void Finish(const SolveSummary& summary);
  // Adds `error_estimate` to result.json (call before Finish).
  void SetErrorEstimate(const ErrorEstimate& estimate);

  const std::filesystem::path& directory() const { return directory_; }

 private:
  nlohmann::json Document(const SolveSummary& summary, const std::string& status) const;
  // Through a temporary file that is renamed: never half a file.
  void Write(const nlohmann::json& document) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::filesystem::path directory_;
};

// Status word of a run's result ("converged", "failed", "cancelled").
std::string ResultStatus(Termination termination);

}  // namespace drape
