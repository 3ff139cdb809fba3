// A run with every converged step kept, what its probes read, and whether its
// summary warns of something (the augmentation and path-following tests).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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

// With the scene's own solver settings.
inline Outcome SolveRecorded(const Scene& scene) {
  return SolveRecorded(scene, SolverOptions::FromScene(scene.solver));
}

inline Eigen::Vector3d Probe(const StepState& s, const std::string& name) {
  for (const auto& p : s.probes)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no probe " << name;
  return {};
}

// The run's steps and iterations, stage by stage, for the test's log.
inline void PrintStages(const char* label, const SolveSummary& summary) {
  std::printf("  %s: %d steps, %d iterations, %.3f s\n",
              label,
              summary.steps,
              summary.iterations,
              summary.total_s);
  for (const auto& st : summary.stages)
    std::printf("    stage %-3s %5d steps %6d iterations %3d cut-backs\n",
                st.name.c_str(),
                st.steps,
                st.iterations,
                st.step_cuts);
}

inline bool Warned(const SolveSummary& summary, const std::string& what) {
  return std::any_of(summary.warnings.begin(), summary.warnings.end(), [&](const std::string& w) {
    return w.find(what) != std::string::npos;
  });
}

}  // namespace test
}  // namespace drape
