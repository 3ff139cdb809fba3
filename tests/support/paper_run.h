// A shipped scene of the seed paper's experiments solved to its end, and the
// force balance every resting state must meet (paper_contact_test.cc and
// paper_contact_slow_test.cc).
#pragma once

#include <gtest/gtest.h>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace test {

struct PaperRun {
  SolveSummary summary;
  StepState last;
  double weight = 0;
};

inline PaperRun SolvePaperScene(const char* file) {
  const Scene scene = ReadScene(test::ScenesDir() / file);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  PaperRun run;
  run.summary = solver.Solve({[&](const StepState& step) {
    run.last = step;
    return StepDecision::kContinue;
  }});
  run.weight = solver.model().total_weight.norm();
  return run;
}

// Everything that holds the fabric, at rest, carries its weight.
inline void ExpectForceBalance(const PaperRun& run, double tolerance) {
  Eigen::Vector3d held = run.last.contact->force;
  for (const auto& r : run.last.reactions) held += r.value;
  EXPECT_NEAR(held.z(), run.weight, tolerance * run.weight);
  EXPECT_NEAR(held.head<2>().norm(), 0.0, tolerance * run.weight);
}

}  // namespace test
}  // namespace drape
