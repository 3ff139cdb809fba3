// A stage's path under arc-length control: steps of length Δs along the
// path (ArcLengthStepper), through limit points, and onto a stable branch at
// a bifurcation.
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/continuation/step_policy.h"
#include "core/model/string_format.h"
#include "core/solve/bifurcation_passage.h"
#include "core/solve/converged_step.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/snap_passage.h"
#include "core/solve/stage_runner.h"

namespace drape {
namespace {

// A snap-back may take λ below 0 for a while (a load that must reverse to
// hold the shell on its path); a path that runs back past this does not come
// back to the stage's end.
constexpr double kLowestLambda = -1.0;

// Snaps at limit points this close in λ (relative) are at one place: after
// the second the path is going round between two rest states whose folds
// nearly meet (an imperfection's cusp), and it jumps past them instead.
constexpr double kSamePlace = 1e-4;
constexpr int kSnapsAtOnePlace = 2;

StageOutcome TurnsTooOften(const Stage& spec, int index, int turns, double lambda) {
  return StageOutcome::Stop(
      Termination::kStepTooSmall,
      Format("stage '%s' (stages[%d]): the path turned back %d times (solver.max_turns) and is at "
             "λ = %.6g: between its limit points a real part snaps, and this path goes back and "
             "forth instead; solver.branching: stable takes the snaps, or allow more turns",
             spec.name.c_str(),
             index,
             turns,
             lambda));
}

StageOutcome RunsBackTooFar(const Stage& spec, int index) {
  return StageOutcome::Stop(Termination::kStepTooSmall,
                            "stage '" + spec.name +
                                "': the path runs back past λ = −1 and does not reach the "
                                "stage's end: past its limit points the part would snap, a jump no "
                                "quasi-static path follows; change what the stage does (stages[" +
                                std::to_string(index) +
                                "]) or hold the part more (supports, grippers)");
}

// Where the stage's path stands between steps.
struct PathPosition {
  double lambda = 0;
  double arc_length = 0;      // of the next step; 0: size the first step from Δλ₀
  double max_arc_length = 0;  // set from the first step: max_increment in its units
  std::optional<PathDirection> previous;
  double last_landing = NAN;  // λ where the last branch switch landed
  double last_snap = NAN;     // λ where the last snap at a limit point landed
  int snaps_here = 0;         // snaps in a row at last_snap's λ
  double lowest = 0;          // the smallest λ the path reached
  int turns = 0;              // limit points passed

  // After a jump the path starts afresh where the part landed, its first
  // step sized from Δλ₀.
  void GoOnAfterSnap(double landed) {
    lambda = landed;
    arc_length = 0;
    previous.reset();
  }

  // From where a bifurcation's passage left the part: the first point on
  // the branch it switched to, or where it snapped (no direction: a rest
  // state, not a path).
  void GoOnFromBranch(const PathPoint& branch, ArcLengthStepper& stepper) {
    if (branch.step.direction.translation.size() == 0) return GoOnAfterSnap(branch.lambda);
    // Landing where the last switch landed: forward from there led back to
    // the same bifurcation (the branch bends back; the part would snap). Let
    // the path go the way the switch pointed instead of round again.
    if (std::abs(branch.lambda - last_landing) < 1e-6) stepper.SetDefiniteGoesForward(false);
    last_landing = branch.lambda;
    lambda = branch.lambda;
    previous = branch.step.direction;
    // Grow from the switch's own length: the branch starts near the point.
    arc_length = std::min(branch.step.arc_length, max_arc_length);
  }
};

// A step that did not converge (the state restored): cut back, or, for a
// stage stuck at its start, let the part snap from there.
StageOutcome AfterFailedStep(SolveRun& run,
                             int index,
                             const StageLoading& loading,
                             const ContinuationStep& step,
                             PathPosition& at,
                             int& cuts_in_a_row,
                             int& stalled_in_a_row,
                             StageSummary& stage) {
  const Stage& spec = run.scene.stages[index];
  StageOutcome o = CutBack(run, step, spec, at.lambda, cuts_in_a_row, stage);
  if (o.GoesOn()) {
    at.arc_length = 0.5 * step.arc_length;
    return o;
  }
  PathPoint landed;
  if (CanSnapFromStart(run, stage, at.lambda, o)) {
    if (StageOutcome s = SnapFromStart(run, index, loading, o, stage, landed); !s.GoesOn())
      return s;
  } else if (CanSnapWhereStalled(run, stage, at.lambda, stalled_in_a_row, o)) {
    if (StageOutcome s = SnapWhereStalled(run, index, loading, o, at.lambda, stage, landed);
        !s.GoesOn())
      return s;
    ++stalled_in_a_row;
  } else {
    return o;
  }
  at.GoOnAfterSnap(landed.lambda);
  cuts_in_a_row = 0;
  return StageOutcome::On();
}

}  // namespace

StageOutcome RunArcLength(SolveRun& run,
                          int index,
                          const StageLoading& loading,
                          StageSummary& stage) {
  const Stage& spec = run.scene.stages[index];
  const SolverOptions& options = run.options;
  ArcLengthStepper stepper = run.Stepper(loading);
  const StepPolicy policy = options.Stepping();
  PathPosition at;
  int cuts_in_a_row = 0, stalled_in_a_row = 0;
  while (at.lambda < 1.0 - 1e-12) {
    if (run.summary.steps >= options.max_steps) return MaxStepsReached(run, spec, at.lambda);
    const ShellState saved = run.state;
    const PathDirection* previous = at.previous ? &*at.previous : nullptr;
    ContinuationStep step = stepper.Step(run.state,
                                         {.lambda = at.lambda,
                                          .arc_length = at.arc_length,
                                          .first_increment = spec.initial_increment,
                                          .previous = previous,
                                          .target = 1.0},
                                         run.cancel);
    run.CountIterations(step.iterations, stage);
    if (at.max_arc_length == 0)
      at.max_arc_length = step.arc_length * options.max_increment / spec.initial_increment;
    if (step.status != NewtonOutcome::Status::kConverged) {
      run.state = saved;
      if (StageOutcome o = AfterFailedStep(
              run, index, loading, step, at, cuts_in_a_row, stalled_in_a_row, stage);
          !o.GoesOn())
        return o;
      continue;
    }
    // With friction the contact passes come before the step is judged: a
    // step whose lag does not settle is cut. (Without, they follow it.)
    std::optional<Augmentation> passes;
    if (run.contact && run.contact->friction() > 0 &&
        !PassContact(run, step.landed ? 1.0 : step.lambda, loading, step, passes.emplace())) {
      run.state = saved;
      if (StageOutcome o = AfterFailedStep(
              run, index, loading, step, at, cuts_in_a_row, stalled_in_a_row, stage);
          !o.GoesOn())
        return o;
      continue;
    }
    if (step.lambda < kLowestLambda) return RunsBackTooFar(spec, index);
    cuts_in_a_row = 0;
    stalled_in_a_row = 0;
    const std::optional<StabilityEvent> event =
        PivotChange(run, stepper, step, run.lambda_direction);
    auto crossing = [&] {
      return Crossing{
          PathPoint{saved, at.lambda, {}}, previous, PathPoint{run.state, event->lambda, step}};
    };
    if (event && SnapsAt(run, *event, step)) {
      PathPoint landed;
      if (at.snaps_here >= kSnapsAtOnePlace) {
        // From the last landing, down by energy at a larger λ.
        run.state = saved;
        const StageOutcome round = StageOutcome::Stop(
            Termination::kStepTooSmall,
            Format("stage '%s' (stages[%d]): the path snaps back and forth between two rest "
                   "states at λ = %.6g",
                   spec.name.c_str(),
                   index,
                   at.last_snap));
        if (StageOutcome o = SnapWhereStalled(run, index, loading, round, at.lambda, stage, landed);
            !o.GoesOn())
          return o;
        at.snaps_here = 0;
      } else {
        if (StageOutcome o = SnapAtLimit(run, index, loading, stepper, crossing(), stage, landed);
            !o.GoesOn())
          return o;
        const bool here = std::abs(landed.lambda - at.last_snap) <=
                          kSamePlace * std::max(std::abs(at.last_snap), 1e-3);
        at.snaps_here = here ? at.snaps_here + 1 : 1;
      }
      at.last_snap = landed.lambda;
      at.GoOnAfterSnap(landed.lambda);
      continue;
    }
    if (event && event->kind == StabilityKind::kLimit && ++at.turns > options.max_turns)
      return TurnsTooOften(spec, index, at.turns, step.lambda);
    if (event && SwitchesAt(run, *event, step)) {
      PathPoint branch;
      if (StageOutcome o =
              PassBifurcation(run, index, loading, stepper, crossing(), *event, stage, branch);
          !o.GoesOn())
        return o;
      at.GoOnFromBranch(branch, stepper);
      continue;
    }
    at.lambda = step.landed ? 1.0 : step.lambda;
    at.lowest = std::min(at.lowest, at.lambda);
    at.previous = step.direction;
    ++stage.steps;
    stage.final_lambda = at.lambda;
    run.stage_path_length += step.arc_length;
    if (StageOutcome o = RecordConvergedStep(run,
                                             {index, stage.steps, at.lambda},
                                             loading,
                                             step,
                                             event ? &*event : nullptr,
                                             passes ? &*passes : nullptr);
        !o.GoesOn())
      return o;
    if (run.slides_as_a_whole) {
      // Friction cannot hold the part here: find where it comes to rest.
      PathPoint landed;
      const SnapStart start{
          PathPoint{run.state, at.lambda, step}, run.state, at.lambda, SnapTrigger::kSliding, 0};
      if (StageOutcome o = Snap(run, index, loading, start, false, stage, landed); !o.GoesOn())
        return o;
      at.GoOnAfterSnap(landed.lambda);
      continue;
    }
    at.arc_length = std::min(policy.Next(step.arc_length, step.iterations), at.max_arc_length);
  }
  if (at.lowest < -1e-6) run.summary.warnings.push_back(ReversedLoadWarning(spec, at.lowest));
  return StageOutcome::On();
}

}  // namespace drape
