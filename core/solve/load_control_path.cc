// A stage's path under load control: λ in increments, each a tangent
// predictor and Newton at the increment's end.
#include <algorithm>
#include <optional>

#include "core/continuation/step_policy.h"
#include "core/solve/bifurcation_passage.h"
#include "core/solve/converged_step.h"
#include "core/solve/snap_passage.h"
#include "core/solve/stage_runner.h"

namespace drape {
namespace {

// Near a bifurcation λ grows with the square of the amplitude: after a switch
// the next increment is this many times the switch's rise in λ (which doubles
// the amplitude), where a full-size step's tangent predictor would shoot far
// along the nearly free mode. Acceleration grows it back.
constexpr double kIncrementAfterSwitch = 3;
// ... and at least this fraction of the stage's Δλ₀.
constexpr double kSmallestIncrementAfterSwitch = 1e-4;

}  // namespace

StageOutcome RunLoadControl(SolveRun& run,
                            int index,
                            const StageLoading& loading,
                            StageSummary& stage) {
  const Stage& spec = run.scene.stages[index];
  const SolverOptions& options = run.options;
  ArcLengthStepper stepper = run.Stepper(loading);
  const StepPolicy policy = options.Stepping();
  double lambda = 0;
  double increment = spec.initial_increment;
  int cuts_in_a_row = 0;
  while (lambda < 1.0) {
    if (run.summary.steps >= options.max_steps) return MaxStepsReached(run, spec, lambda);
    increment = std::min({increment, options.max_increment, 1.0 - lambda});
    // Land exactly on λ = 1 rather than leave a sliver of a step.
    if (1.0 - (lambda + increment) < 1e-12) increment = 1.0 - lambda;
    const ShellState saved = run.state;
    ContinuationStep step = stepper.StepTo(run.state, lambda, lambda + increment, run.cancel);
    run.CountIterations(step.iterations, stage);
    if (step.status != NewtonOutcome::Status::kConverged) {
      run.state = saved;
      if (StageOutcome o = CutBack(run, step, spec, lambda, cuts_in_a_row, stage); !o.GoesOn()) {
        if (!CanSnapFromStart(run, stage, lambda, o)) return o;
        PathPoint landed;
        if (StageOutcome s = SnapFromStart(run, index, loading, o, stage, landed); !s.GoesOn())
          return s;
        lambda = landed.lambda;
        increment = spec.initial_increment;
        cuts_in_a_row = 0;
        continue;
      }
      increment /= 2;
      continue;
    }
    cuts_in_a_row = 0;
    const std::optional<StabilityEvent> event =
        PivotChange(run, stepper, step, run.lambda_direction);
    if (event && SwitchesAt(run, *event, step)) {
      // Located and switched with arc-length steps (the step's own length in
      // their metric); load control goes on from the branch.
      step.arc_length = stepper.Length(step.direction, lambda + increment, run.state);
      PathPoint branch;
      const Crossing crossing{
          PathPoint{saved, lambda, {}}, nullptr, PathPoint{run.state, lambda + increment, step}};
      if (StageOutcome o =
              PassBifurcation(run, index, loading, stepper, crossing, *event, stage, branch);
          !o.GoesOn())
        return o;
      increment = run.summary.stability_events.back().kind == StabilityKind::kSnap
                      ? spec.initial_increment  // the part landed at rest: start afresh
                      : std::max(kIncrementAfterSwitch *
                                     (branch.lambda - run.summary.stability_events.back().lambda),
                                 kSmallestIncrementAfterSwitch * spec.initial_increment);
      lambda = branch.lambda;
      continue;
    }
    lambda += increment;
    ++stage.steps;
    stage.final_lambda = lambda;
    run.stage_path_length += stepper.Length(step.direction, lambda, run.state);
    step.arc_length = increment;
    if (StageOutcome o = RecordConvergedStep(
            run, {index, stage.steps, lambda}, loading, step, event ? &*event : nullptr);
        !o.GoesOn())
      return o;
    increment = policy.Next(increment, step.iterations);
  }
  return StageOutcome::On();
}

}  // namespace drape
