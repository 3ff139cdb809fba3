// Mesh sequencing (mesh_sequencing.h): a stage's path followed on a coarser
// mesh, its end carried onto this mesh and brought to equilibrium there.
#include <algorithm>
#include <chrono>
#include <string>

#include "core/model/string_format.h"
#include "core/solve/converged_step.h"
#include "core/solve/mesh_sequencing.h"
#include "core/solve/shell_solver.h"
#include "core/solve/stage_runner.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

SystemTimers TimersOf(const SolveSummary& s) {
  return SystemTimers{s.assembly_s,
                      s.factorization_s,
                      s.solve_s,
                      s.factorizations,
                      s.indefinite_factorizations,
                      s.reused_factorizations};
}

}  // namespace

StageOutcome RunSequenced(SolveRun& run,
                          int index,
                          const StageLoading& loading,
                          StageSummary& stage) {
  const auto begin = Clock::now();
  const Scene coarse_scene = CoarsenedScene(run.scene, run.options.sequencing);
  SolverOptions coarse_options = run.options;
  coarse_options.sequencing = 1;
  ShellSolver coarse(coarse_scene, coarse_options);
  const SolveSummary path = coarse.Solve({}, run.cancel);
  run.CountIterations(path.iterations, stage);
  run.retired_timers += TimersOf(path);
  if (path.termination == Termination::kCancelled)
    return StageOutcome::Cancelled("in stage '" + stage.name + "' (on the coarse mesh)");
  // What the coarse path met (a bifurcation switched, penetration short of
  // its target) is part of this run's story.
  for (const auto& w : path.warnings)
    if (std::find(run.model.warnings.begin(), run.model.warnings.end(), w) ==
        run.model.warnings.end())
      run.summary.notes.push_back("on the coarse mesh: " + w);
  const auto [nx, ny] = *coarse_scene.fabric.mesh.elements;
  const std::string where =
      Format("mesh sequencing%s: the path on %d x %d elements (%d steps, %d iterations, %.3g s)",
             run.options.sequencing_auto
                 ? Format(" (solver.sequencing: auto chose %d)", run.options.sequencing).c_str()
                 : "",
             nx,
             ny,
             path.steps,
             path.iterations,
             path.total_s);
  auto fall_back = [&](const std::string& why) {
    run.summary.notes.push_back(where + " " + why +
                                "; the path was followed on the scene's own mesh instead");
    run.state = run.model.reference;
    run.state.obstacles.assign(run.scene.obstacles.size(), ObstaclePlacement{});
    if (run.contact) run.contact->Commit(run.state);
    return RunPath(run, index, loading, stage);
  };
  if (path.termination != Termination::kCompleted) return fall_back("failed: " + path.message);
  run.state = Prolongate(coarse.model(), coarse.state(), run.model);
  const NewtonOutcome newton = run.SolveAtFixedLambda(1.0, loading);
  run.CountIterations(newton.iterations, stage);
  if (newton.status == NewtonOutcome::Status::kCancelled)
    return StageOutcome::Cancelled("in stage '" + stage.name + "'");
  if (newton.status != NewtonOutcome::Status::kConverged)
    return fall_back("ended where Newton on this mesh did not converge (" + newton.reason + ")");
  if (newton.negative_pivots > 0)
    return fall_back("ended where this mesh's tangent has " +
                     std::to_string(newton.negative_pivots) + " negative pivots");
  run.summary.notes.push_back(
      where + Format(", then %d Newton iterations on this mesh from its end (%.3g s in all)",
                     newton.iterations,
                     std::chrono::duration<double>(Clock::now() - begin).count()));
  stage.steps = 1;
  stage.final_lambda = 1;
  return RecordConvergedStep(run, {index, 1, 1.0}, loading, StepOf(newton));
}

}  // namespace drape
