// The one solver behind the command line, the GUI and the tests: runs a
// scene's stages in order and hands each converged step to observers.
//
//   ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
//   SolveSummary summary = solver.Solve({observer}, &token);
//   std::cout << summary.FullReport();
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "core/solve/solve_summary.h"
#include "core/solve/solver_options.h"
#include "core/solve/step_state.h"

namespace drape {

struct DragBasis;  // gripper_drag.h

class ShellSolver {
 public:
  // Builds the model; throws SceneError for what the engine cannot model.
  ShellSolver(const Scene& scene, const SolverOptions& options);
  // On a model already built (and possibly changed) from `scene`.
  ShellSolver(const Scene& scene, ShellModel model, const SolverOptions& options);
  ~ShellSolver();
  ShellSolver(const ShellSolver&) = delete;
  ShellSolver& operator=(const ShellSolver&) = delete;

  // Runs every stage from the reference state. Observers see each converged
  // step in order; `cancel` is checked between Newton iterations.
  SolveSummary Solve(const std::vector<StepObserver>& observers,
                     const CancellationToken* cancel = nullptr);

  const ShellModel& model() const;
  const ShellState& state() const;  // the last converged state

  // Where a drag of `gripper` goes on from after a run that completed every
  // stage: the last state and the system that holds it (gripper_drag.h).
  // Throws std::invalid_argument naming what is missing.
  DragBasis BasisForDrag(const std::string& gripper);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace drape
