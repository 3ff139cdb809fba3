// Stages and passes at λ = 1: a hold, and the settle passes that leave a
// stage held only by contact in equilibrium without its stabilisation springs.
#include "core/solve/converged_step.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/snap_passage.h"
#include "core/solve/stage_runner.h"

namespace drape {
namespace {

// Each settle pass shrinks the springs' force by about k_s / k of the
// structure; a few passes reach round-off of the weight.
constexpr int kMaxSettlePasses = 5;
// A pass that leaves the springs more than this share of their force did
// not settle the part: it slid on them (friction cannot hold it).
constexpr double kSliding = 0.5;

// The part goes to the rest state the minimiser finds without the springs,
// or the run says that nothing holds it.
StageOutcome SettleByJump(SolveRun& run,
                          int index,
                          const StageLoading& loading,
                          StageSummary& stage) {
  const SnapStart start{PathPoint{run.state, 1.0, {}}, run.state, 1.0, SnapTrigger::kSliding, 0};
  PathPoint landed;
  return Snap(run, index, loading, start, /*record_before=*/false, stage, landed);
}

}  // namespace

StageOutcome RunHold(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage) {
  const ShellState held = run.state;
  const NewtonOutcome newton = run.SolveAtFixedLambda(1.0, loading);
  // Released where it cannot rest without its grippers (pressed into an
  // obstacle, stretched against friction), the part jumps: Newton from the
  // held state may not reach where it lands, the minimiser does.
  if (newton.status != NewtonOutcome::Status::kConverged &&
      newton.status != NewtonOutcome::Status::kCancelled &&
      !run.scene.stages[index].release.empty()) {
    run.CountIterations(newton.iterations, stage);
    run.state = held;
    const SnapStart start{PathPoint{run.state, 1.0, {}}, run.state, 1.0, SnapTrigger::kRelease, 0};
    PathPoint landed;
    return Snap(run, index, loading, start, /*record_before=*/false, stage, landed);
  }
  if (StageOutcome o = run.FixedLambdaOutcome(newton, stage, "found no equilibrium"); !o.GoesOn())
    return o;
  stage.steps = 1;
  stage.final_lambda = 1;
  return RecordConvergedStep(run, {index, 1, 1.0}, loading, StepOf(newton));
}

StageOutcome Settle(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage) {
  // Stop at round-off of the weight.
  const double negligible = 1e-12 * run.model.total_weight.norm();
  double previous = run.last_stabilization_force;
  for (int pass = 0; pass < kMaxSettlePasses; ++pass) {
    if (run.last_stabilization_force <= negligible) return StageOutcome::On();
    if (pass > 0 && run.last_stabilization_force > kSliding * previous)
      return SettleByJump(run, index, loading, stage);
    previous = run.last_stabilization_force;
    const NewtonOutcome newton = run.SolveAtFixedLambda(1.0, loading);
    if (StageOutcome o =
            run.FixedLambdaOutcome(newton, stage, "did not settle without its stabilisation");
        !o.GoesOn())
      return o;
    if (newton.iterations == 0) return StageOutcome::On();  // in equilibrium without them
    ++stage.steps;
    if (StageOutcome o =
            RecordConvergedStep(run, {index, stage.steps, 1.0}, loading, StepOf(newton));
        !o.GoesOn())
      return o;
  }
  if (run.last_stabilization_force > negligible)
    run.summary.notes.push_back(UnsettledNote(
        stage.name, run.last_stabilization_force, run.model.total_weight.norm(), kMaxSettlePasses));
  return StageOutcome::On();
}

}  // namespace drape
