// The stages of a run, one function each way a stage goes: a hold (Newton at
// λ = 1), a path under load or arc-length control, a path found on a coarser
// mesh first (sequencing), and the settle passes after a stage held only by
// contact. Each returns how the stage ended as a value; the converged steps
// go through RecordConvergedStep (converged_step.h).
#pragma once

#include "core/continuation/arc_length_stepper.h"
#include "core/fe/stage_loading.h"
#include "core/solve/solve_run.h"

namespace drape {

// Runs stage `index` from run.state: its releases, DOFs, loading and path.
StageOutcome RunStage(SolveRun& run, int index);

// Newton at λ = 1 from the present state.
StageOutcome RunHold(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage);
// Re-solves at the stage's end, springs re-anchored, until their force is
// negligible: the stage then ends in the equilibrium without them.
StageOutcome Settle(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage);
// The stage's path, by the control it asks for.
StageOutcome RunPath(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage);
StageOutcome RunLoadControl(SolveRun& run,
                            int index,
                            const StageLoading& loading,
                            StageSummary& stage);
StageOutcome RunArcLength(SolveRun& run,
                          int index,
                          const StageLoading& loading,
                          StageSummary& stage);
// The stage's path on the coarsened mesh, then Newton on this one from its
// interpolated end (mesh_sequencing.h). Falls back to the path on this mesh,
// with a note, when the coarse run fails or the end is not stable.
StageOutcome RunSequenced(SolveRun& run,
                          int index,
                          const StageLoading& loading,
                          StageSummary& stage);

// A failed step: a stop when it was cancelled or when `cuts_in_a_row` has
// reached options.max_step_cuts; otherwise the cut-back is counted (the
// caller halves the step) and the stage goes on.
StageOutcome CutBack(SolveRun& run,
                     const ContinuationStep& step,
                     const Stage& spec,
                     double lambda,
                     int& cuts_in_a_row,
                     StageSummary& stage);

// A stop for a stage that needed more than options.max_steps steps.
StageOutcome MaxStepsReached(const SolveRun& run, const Stage& spec, double lambda);

// A fixed-λ Newton solve as a step of a path.
ContinuationStep StepOf(const NewtonOutcome& newton);

}  // namespace drape
