#include "core/solve/bifurcation_passage.h"

#include "core/model/string_format.h"
#include "core/solve/converged_step.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/snap_passage.h"

namespace drape {
namespace {

// Locating a bifurcation: the bracket's arc length at most this fraction of
// the stage's path up to it (λ_c to about 0.1 % where λ dominates Δs).
constexpr double kLocateFraction = 1e-3;
// The step onto a secondary branch: this fraction of the part's diagonal
// along the critical mode (0.2 mm on a 20 cm strip). Small enough to start
// the branch near the point, large enough that the branch's tangent is
// definite by more than round-off.
constexpr double kSwitchAmplitude = 1e-3;

// No stable branch: the part snaps, from the primary path just past the
// point, pushed along the critical mode the way the imperfection leans.
StageOutcome SnapAtBifurcation(SolveRun& run,
                               int index,
                               const StageLoading& loading,
                               const Crossing& crossing,
                               const BranchSwitch& sw,
                               const BifurcationSettings& settings,
                               StageSummary& stage,
                               PathPoint& reached) {
  SnapStart start{sw.bifurcation ? *sw.bifurcation : crossing.start,
                  sw.past.state,
                  sw.past.lambda,
                  SnapTrigger::kBifurcation,
                  sw.negative_pivots_fundamental};
  const bool against =
      settings.imperfection.size() == sw.mode.size() && sw.mode.dot(settings.imperfection) < 0;
  Eigen::VectorXd push = run.dofs->Expand(sw.mode);
  push *= (against ? -1 : 1) * settings.amplitude / std::max(MaxTranslation(push), 1e-300);
  push *= run.system->StepBound(start.pushed, push);  // not into an obstacle's barrier
  ApplyIncrement(push, start.pushed);
  return Snap(run, index, loading, start, sw.bifurcation.has_value(), stage, reached);
}

}  // namespace

BifurcationSettings PassageSettings(const SolveRun& run) {
  BifurcationSettings settings;
  settings.locate_fraction = kLocateFraction;
  settings.path_before = run.stage_path_length;
  settings.amplitude = kSwitchAmplitude * run.model.characteristic_length;
  settings.rotation_length = run.element_size;
  if (run.imperfection.size() == run.model.DofCount())
    settings.imperfection = run.dofs->Restrict(run.imperfection);
  return settings;
}

StageOutcome RecordPathPoint(SolveRun& run,
                             int index,
                             const StageLoading& loading,
                             const PathPoint& point,
                             StageSummary& stage,
                             const StabilityEvent* event,
                             const Augmentation* passes) {
  ++stage.steps;
  stage.final_lambda = point.lambda;
  return RecordConvergedStep(
      run, {index, stage.steps, point.lambda}, loading, point.step, event, passes);
}

StabilityEvent ClassifyPivotChange(int direction_before, int direction, double lambda) {
  StabilityEvent e;
  e.kind = direction != direction_before ? StabilityKind::kLimit : StabilityKind::kBifurcation;
  e.branch = e.kind == StabilityKind::kLimit ? Branch::kNone : Branch::kFundamental;
  e.lambda = lambda;
  return e;
}

std::optional<StabilityEvent> PivotChange(const SolveRun& run,
                                          ArcLengthStepper& stepper,
                                          const ContinuationStep& step,
                                          int& direction) {
  if (step.negative_pivots == run.recorder->last_negative_pivots()) return std::nullopt;
  const int now = stepper.LambdaDirection(run.state, step.lambda, step.direction);
  const StabilityEvent event = ClassifyPivotChange(direction, now, step.lambda);
  direction = now;
  return event;
}

bool LosesStability(const SolveRun& run, const ContinuationStep& step) {
  return run.recorder->last_negative_pivots() == 0 && step.negative_pivots > 0 &&
         run.options.branching == Branching::kStable;
}

bool SwitchesAt(const SolveRun& run, const StabilityEvent& event, const ContinuationStep& step) {
  return event.kind == StabilityKind::kBifurcation && LosesStability(run, step);
}

StageOutcome PassBifurcation(SolveRun& run,
                             int index,
                             const StageLoading& loading,
                             ArcLengthStepper& stepper,
                             const Crossing& crossing,
                             StabilityEvent event,
                             StageSummary& stage,
                             PathPoint& reached) {
  const std::string& name = run.scene.stages[index].name;
  const BifurcationSettings settings = PassageSettings(run);
  const int before = run.recorder->last_negative_pivots();
  const BranchSwitch sw = SwitchBranch(stepper,
                                       *run.system,
                                       crossing.start,
                                       crossing.previous,
                                       crossing.past,
                                       before,
                                       settings,
                                       run.cancel);
  run.CountIterations(sw.iterations, stage);
  if (sw.cancelled) {
    run.state = crossing.start.state;
    return StageOutcome::Cancelled("in stage '" + name + "' at a bifurcation");
  }
  if (!sw.switched && sw.mode.size() > 0 && run.options.branching == Branching::kStable)
    return SnapAtBifurcation(run, index, loading, crossing, sw, settings, stage, reached);
  if (!sw.switched) {
    // Keep the last stable point the bisection found: the part's state just
    // before it would snap.
    run.state = crossing.start.state;
    if (sw.bifurcation) {
      run.state = sw.bifurcation->state;
      if (StageOutcome o = RecordPathPoint(run, index, loading, *sw.bifurcation, stage);
          !o.GoesOn())
        return o;
    }
    return StageOutcome::Stop(
        Termination::kNoStableBranch,
        Format("stage '%s': the path bifurcates at λ = %.6g (negative pivots %d -> %d) and "
               "no branch past it could be followed: ",
               name.c_str(),
               sw.lambda,
               before,
               sw.negative_pivots_fundamental) +
            sw.failure +
            ". The primary path past it is unstable; solver.branching: fundamental follows "
            "it anyway" +
            ContactHint(run));
  }
  if (sw.bifurcation) {
    run.state = sw.bifurcation->state;
    run.stage_path_length += sw.bifurcation->step.arc_length;
    if (StageOutcome o = RecordPathPoint(run, index, loading, *sw.bifurcation, stage); !o.GoesOn())
      return o;
  }
  run.state = sw.branch.state;
  event.lambda = sw.lambda;
  event.branch = sw.kind;
  event.negative_pivots_fundamental = sw.negative_pivots_fundamental;
  event.modes = sw.modes;
  event.mode_max_displacement = sw.max_displacement;
  event.switch_iterations = sw.iterations;
  event.switch_s = sw.seconds;
  ++run.summary.branch_switches;
  run.stage_path_length += sw.branch.step.arc_length;
  reached = sw.branch;
  return RecordPathPoint(run, index, loading, sw.branch, stage, &event);
}

}  // namespace drape
