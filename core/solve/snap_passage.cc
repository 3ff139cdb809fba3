#include "core/solve/snap_passage.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/continuation/energy_minimiser.h"
#include "core/model/string_format.h"
#include "core/solve/converged_step.h"
#include "core/solve/run_diagnostics.h"

namespace drape {
namespace {

// Past a located limit point the part jumps at λ_c(1 + kPastLimit): the
// bracket gives λ_c to about the square of its length, and just above λ_c
// the stable state near the fold no longer exists. Where the minimiser still
// falls back onto it, the margin grows tenfold, at most kLimitTries times.
constexpr double kPastLimit = 1e-5;
constexpr int kLimitTries = 3;
// The minimiser's corrections, in units of the options' Newton limit: a jump
// takes tens of steps where a path step takes one.
constexpr int kMinimiserIterationsPerNewton = 40;
// A stalled path jumps this fraction of the stage's first increment past
// where it stalled; at most kStalledSnaps times without a step converging
// between them, so that a path the stepper cannot follow is not crossed
// jump by jump.
constexpr double kStalledIncrement = 0.1;
constexpr int kStalledSnaps = 5;

double LargestTranslation(const ShellState& from, const ShellState& to) {
  return (to.positions - from.positions).rowwise().norm().maxCoeff();
}

// The minimiser run at the start's λ, from its pushed state.
struct Jump {
  MinimiserOutcome outcome;
  ShellState state;
  double seconds = 0;
};

Jump JumpFrom(SolveRun& run, const StageLoading& loading, const SnapStart& start) {
  const auto clock = std::chrono::steady_clock::now();
  Jump jump;
  jump.state = start.pushed;
  loading.Place(start.lambda, jump.state);
  const StabilizationOff springs(run.contact.get());
  MinimiserSettings settings;
  settings.newton = run.Newton();
  settings.newton.max_iterations *= kMinimiserIterationsPerNewton;
  jump.outcome = MinimiseEnergy(
      *run.system,
      [&](const ShellState& s) { return loading.External(start.lambda, s); },
      settings,
      jump.state,
      run.cancel);
  jump.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return jump;
}

// Why the part jumps, as the message's clause before "at λ = …".
const char* SnapCause(SnapTrigger trigger) {
  switch (trigger) {
    case SnapTrigger::kStart:
      return "where it starts it cannot carry its first increment, so";
    case SnapTrigger::kLimit:
      return "past a limit point";
    case SnapTrigger::kBifurcation:
      return "past a bifurcation point";
    case SnapTrigger::kSliding:
      return "every node in contact slides, held only by the stabilisation springs, so";
    case SnapTrigger::kRelease:
      return "released from its grippers where it cannot rest without them,";
    case SnapTrigger::kStalled:
      return "where its path cannot be followed (every cut-back of the step failed), just";
  }
  return "?";
}

// What to change when a jump finds no rest state.
std::string SnapAdvice(const SolveRun& run,
                       const ShellState& before,
                       SnapTrigger trigger,
                       const MinimiserOutcome& outcome) {
  if (outcome.unheld) {
    std::string on;
    if (run.contact)
      for (const std::string& name : run.contact->TouchedObstacles(before))
        on += (on.empty() ? "" : ", ") + ("'" + name + "'");
    const std::string slides = on.empty() ? "" : "; it slides off " + on;
    if (run.contact && run.contact->friction() > 0)
      return Format(
          "%s. Hold the part (supports, grippers) or give it more friction "
          "(contact.friction is %.3g)",
          slides.c_str(),
          run.contact->friction());
    return slides +
           ". Hold the part (supports, grippers) or let friction hold it (contact.friction)";
  }
  if (trigger == SnapTrigger::kStart)
    return ". Hold the part more (supports, grippers) or give it bending (material.bending)";
  return ". solver.branching: fundamental follows the unstable path instead";
}

StageOutcome RecordSnap(SolveRun& run,
                        int index,
                        const StageLoading& loading,
                        const SnapStart& start,
                        const Jump& jump,
                        bool record_before,
                        StageSummary& stage,
                        PathPoint& landed,
                        bool jumped = true) {
  run.CountIterations(jump.outcome.newton.iterations, stage);
  const std::string& name = run.scene.stages[index].name;
  const NewtonOutcome& newton = jump.outcome.newton;
  run.state = start.before.state;
  if (newton.status == NewtonOutcome::Status::kCancelled)
    return StageOutcome::Cancelled("in stage '" + name + "' while it snapped");
  // The last stable point before the jump is recorded as the bracket found
  // it: re-lagging friction there would move a point this close to the
  // critical one across it.
  const Augmentation none;
  const bool with_friction = run.contact && run.contact->friction() > 0;
  if (record_before)
    if (StageOutcome o = RecordPathPoint(
            run, index, loading, start.before, stage, nullptr, with_friction ? &none : nullptr);
        !o.GoesOn())
      return o;
  if (newton.status != NewtonOutcome::Status::kConverged)
    return StageOutcome::Stop(
        jump.outcome.unheld ? Termination::kUnheld : Termination::kNoStableBranch,
        Format("stage '%s' (stages[%d]): %s at λ = %.6g the part snaps, but no rest state was "
               "found for it to land in: ",
               name.c_str(),
               index,
               SnapCause(start.trigger),
               start.lambda) +
            newton.reason + SnapAdvice(run, start.before.state, start.trigger, jump.outcome) +
            ContactHint(run));
  StabilityEvent event;
  event.kind = StabilityKind::kSnap;
  event.trigger = start.trigger;
  event.branch = Branch::kNone;
  event.lambda = start.lambda;
  event.negative_pivots_fundamental = start.pivots_past;
  event.energy_released = -jump.outcome.energy_change;
  event.mode_max_displacement = LargestTranslation(start.before.state, jump.state);
  event.switch_iterations = newton.iterations;
  event.switch_s = jump.seconds;
  // The jump slid the part along its obstacles; where it lands, friction
  // starts again from rest (its anchors there), as a new step's would.
  if (run.contact) run.contact->RestartFriction(jump.state);
  landed.state = jump.state;
  landed.lambda = start.lambda;
  landed.step = {};
  landed.step.status = NewtonOutcome::Status::kConverged;
  landed.step.iterations = newton.iterations;
  landed.step.residuals = newton.residuals;
  landed.step.convergence = newton.convergence;
  landed.step.negative_pivots = newton.negative_pivots;
  landed.step.lambda = start.lambda;
  run.state = jump.state;
  run.lambda_direction = 1;
  return RecordPathPoint(run, index, loading, landed, stage, jumped ? &event : nullptr);
}

}  // namespace

bool SnapsAt(const SolveRun& run, const StabilityEvent& event, const ContinuationStep& step) {
  return event.kind == StabilityKind::kLimit && LosesStability(run, step);
}

StageOutcome Snap(SolveRun& run,
                  int index,
                  const StageLoading& loading,
                  const SnapStart& start,
                  bool record_before,
                  StageSummary& stage,
                  PathPoint& landed) {
  const Jump jump = JumpFrom(run, loading, start);
  return RecordSnap(run, index, loading, start, jump, record_before, stage, landed);
}

bool CanSnapFromStart(const SolveRun& run,
                      const StageSummary& stage,
                      double lambda,
                      const StageOutcome& stuck) {
  return stuck.termination == Termination::kStepTooSmall && stage.steps == 0 && lambda == 0 &&
         run.options.branching == Branching::kStable;
}

namespace {

// The jump from where a stage is stuck (`start`), recorded; or `stuck`'s
// stop with what the minimiser found added.
StageOutcome SnapWhereStuck(SolveRun& run,
                            int index,
                            const StageLoading& loading,
                            const StageOutcome& stuck,
                            const SnapStart& start,
                            StageSummary& stage,
                            PathPoint& landed) {
  const Jump jump = JumpFrom(run, loading, start);
  if (jump.outcome.newton.status != NewtonOutcome::Status::kConverged &&
      jump.outcome.newton.status != NewtonOutcome::Status::kCancelled) {
    run.CountIterations(jump.outcome.newton.iterations, stage);
    return StageOutcome::Stop(
        stuck.termination,
        stuck.message + "; nor does it come to rest at λ = " + Format("%.6g", start.lambda) + " (" +
            jump.outcome.newton.reason + ")" +
            (jump.outcome.unheld ? SnapAdvice(run, start.before.state, start.trigger, jump.outcome)
                                 : std::string()));
  }
  return RecordSnap(run, index, loading, start, jump, /*record_before=*/false, stage, landed);
}

}  // namespace

StageOutcome SnapFromStart(SolveRun& run,
                           int index,
                           const StageLoading& loading,
                           const StageOutcome& stuck,
                           StageSummary& stage,
                           PathPoint& landed) {
  const double lambda = std::min(1.0, run.scene.stages[index].initial_increment);
  const SnapStart start{PathPoint{run.state, 0.0, {}}, run.state, lambda, SnapTrigger::kStart, 0};
  return SnapWhereStuck(run, index, loading, stuck, start, stage, landed);
}

bool CanSnapWhereStalled(const SolveRun& run,
                         const StageSummary& stage,
                         double lambda,
                         int stalled_in_a_row,
                         const StageOutcome& stuck) {
  // A part only frictionless contact holds may have no rest to jump to: its
  // stalled path is reported as such (ContactHint), not crossed.
  return stuck.termination == Termination::kStepTooSmall && stage.steps > 0 && lambda > 0 &&
         lambda < 1 && stalled_in_a_row < kStalledSnaps &&
         run.options.branching == Branching::kStable && !HeldOnlyByFrictionlessContact(run);
}

StageOutcome SnapWhereStalled(SolveRun& run,
                              int index,
                              const StageLoading& loading,
                              const StageOutcome& stuck,
                              double lambda,
                              StageSummary& stage,
                              PathPoint& landed) {
  const double past =
      std::min(1.0, lambda + kStalledIncrement * run.scene.stages[index].initial_increment);
  const SnapStart start{
      PathPoint{run.state, lambda, {}}, run.state, past, SnapTrigger::kStalled, 0};
  return SnapWhereStuck(run, index, loading, stuck, start, stage, landed);
}

StageOutcome SnapAtLimit(SolveRun& run,
                         int index,
                         const StageLoading& loading,
                         ArcLengthStepper& stepper,
                         const Crossing& crossing,
                         StageSummary& stage,
                         PathPoint& landed) {
  const int before = run.recorder->last_negative_pivots();
  const CrossingBracket b = LocateCrossing(stepper,
                                           crossing.start,
                                           crossing.previous,
                                           crossing.past,
                                           before,
                                           PassageSettings(run),
                                           run.cancel);
  run.CountIterations(b.iterations, stage);
  if (b.cancelled) {
    run.state = crossing.start.state;
    return StageOutcome::Cancelled("in stage '" + run.scene.stages[index].name +
                                   "' at a limit point");
  }
  // The limit load: the larger λ of the bracket's ends (λ peaks inside it).
  const double limit = std::max(b.lo.lambda, b.hi.lambda);
  // Falling back onto the fold's stable state moves the part by about the
  // bracket's own width; a jump goes much further.
  const double fell_back = 10 * LargestTranslation(b.lo.state, b.hi.state);
  SnapStart start{b.lo, b.hi.state, limit, SnapTrigger::kLimit, b.hi.step.negative_pivots};
  Jump jump;
  bool jumped = false;
  for (int k = 0; k < kLimitTries && !jumped; ++k) {
    if (k > 0) run.CountIterations(jump.outcome.newton.iterations, stage);
    start.lambda =
        std::min(1.0, limit + kPastLimit * std::pow(10.0, k) * std::max(std::abs(limit), 1e-3));
    jump = JumpFrom(run, loading, start);
    if (jump.outcome.newton.status != NewtonOutcome::Status::kConverged) break;
    jumped = LargestTranslation(b.lo.state, jump.state) > fell_back;
  }
  // Still on the fold's stable side: no jump at this λ, the path goes on
  // from the rest state found.
  return RecordSnap(run,
                    index,
                    loading,
                    start,
                    jump,
                    b.lo_s > 0,
                    stage,
                    landed,
                    jumped || jump.outcome.newton.status != NewtonOutcome::Status::kConverged);
}

}  // namespace drape
