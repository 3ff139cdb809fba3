// A run with every converged step kept, and whether its summary warns of
// something (augmentation_test.cc and augmentation_slow_test.cc).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "core/solve/shell_solver.h"

namespace drape {
namespace test {

struct Outcome {
  SolveSummary summary;
  std::vector<StepState> steps;
};

inline Outcome SolveRecorded(const Scene& scene, const SolverOptions& options) {
  ShellSolver solver(scene, options);
  Outcome run;
  run.summary = solver.Solve({[&](const StepState& s) {
    run.steps.push_back(s);
    return StepDecision::kContinue;
  }});
  return run;
}

inline bool Warned(const SolveSummary& summary, const std::string& what) {
  return std::any_of(summary.warnings.begin(), summary.warnings.end(), [&](const std::string& w) {
    return w.find(what) != std::string::npos;
  });
}

}  // namespace test
}  // namespace drape
