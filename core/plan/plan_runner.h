// Evaluations of a plan as `drape run` processes (docs/plan.md): each in
// DIR/evals/sK-eNNNN with its scene, result and log. One evaluation whose
// folder holds the same scene and an ended result is read, not run again:
// that is how a rerun resumes. `drape plan` and the workbench's Plan dock
// both evaluate through it.
#pragma once

#include <atomic>
#include <filesystem>
#include <vector>

#include "core/plan/plan_file.h"
#include "core/plan/plan_outcome.h"

namespace drape {

// DIR/evals/s<start+1>-e<index, four digits>.
std::filesystem::path EvaluationFolder(const std::filesystem::path& dir, int start, int index);

class PlanRunner {
 public:
  // `program`: the `drape` executable; `stop`, when set, cancels the run
  // going on (its result says cancelled, so a rerun makes it again).
  PlanRunner(const Plan& plan,
             std::filesystem::path dir,
             std::filesystem::path program,
             const std::atomic<bool>* stop)
      : plan_(plan), dir_(std::move(dir)), program_(std::move(program)), stop_(stop) {}

  // Runs (or finds) the evaluation at `x`. Throws std::runtime_error when
  // the program cannot be started.
  EvaluationOutcome operator()(int start, int index, const std::vector<double>& x) const;

 private:
  void Run(const std::filesystem::path& folder) const;

  const Plan& plan_;
  std::filesystem::path dir_, program_;
  const std::atomic<bool>* stop_;
};

}  // namespace drape
