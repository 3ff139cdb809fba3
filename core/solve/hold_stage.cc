// Stages and passes at λ = 1: a hold, and the settle passes that leave a
// stage held only by contact in equilibrium without its stabilisation springs.
#include "core/solve/converged_step.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/stage_runner.h"

namespace drape {
namespace {

// Each settle pass shrinks the springs' force by about k_s / k of the
// structure; a few passes reach round-off of the weight.
constexpr int kMaxSettlePasses = 5;

}  // namespace

StageOutcome RunHold(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage) {
  const NewtonOutcome newton = run.SolveAtFixedLambda(1.0, loading);
  if (StageOutcome o = run.FixedLambdaOutcome(newton, stage, "found no equilibrium"); !o.GoesOn())
    return o;
  stage.steps = 1;
  stage.final_lambda = 1;
  return RecordConvergedStep(run, {index, 1, 1.0}, loading, StepOf(newton));
}

StageOutcome Settle(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage) {
  // Stop at round-off of the weight.
  const double negligible = 1e-12 * run.model.total_weight.norm();
  for (int pass = 0; pass < kMaxSettlePasses; ++pass) {
    if (run.last_stabilization_force <= negligible) return StageOutcome::On();
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
