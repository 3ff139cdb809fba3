// Where a path under solver.branching: stable meets a point past which no
// stable path goes on — a limit point of a rising λ, a bifurcation with no
// stable branch — the part snaps: at that λ it jumps to the stable rest state
// the energy minimiser finds (energy_minimiser.h), and the path goes on from
// there. The last stable point before the jump and the landing are recorded
// as two steps at (nearly) the same λ, the landing with a `snap` event.
#pragma once

#include <Eigen/Core>

#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/branch_switch.h"
#include "core/continuation/stability_event.h"
#include "core/fe/stage_loading.h"
#include "core/solve/bifurcation_passage.h"
#include "core/solve/solve_run.h"

namespace drape {

// Whether the run snaps at this event: a limit point met from a stable state
// under `stable` branching (λ would run back along an unstable path).
bool SnapsAt(const SolveRun& run, const StabilityEvent& event, const ContinuationStep& step);

// Where a jump starts: the last stable point before the critical point, the
// state the minimiser starts from (past the point, or moved along its
// unstable mode) and the λ at which the part jumps.
struct SnapStart {
  PathPoint before;
  ShellState pushed;
  double lambda = 0;
  SnapTrigger trigger = SnapTrigger::kLimit;
  int pivots_past = 0;  // on the path just past the point
};

// The jump itself: minimises the energy at `start.lambda` from `start.pushed`,
// records `start.before` (when it is not the stage's last recorded point)
// and the landing, and leaves run.state there; `landed` is its point. A stop
// when no rest state is found (kNoStableBranch, the state before the jump
// kept) or the run was cancelled.
StageOutcome Snap(SolveRun& run,
                  int index,
                  const StageLoading& loading,
                  const SnapStart& start,
                  bool record_before,
                  StageSummary& stage,
                  PathPoint& landed);

// Past a limit point: locates it on the crossing step and snaps from there.
StageOutcome SnapAtLimit(SolveRun& run,
                         int index,
                         const StageLoading& loading,
                         ArcLengthStepper& stepper,
                         const Crossing& crossing,
                         StageSummary& stage,
                         PathPoint& landed);

// Whether a stage stuck at its start can snap: under `stable` branching, its
// first step cut back until it gave up (`stuck`), nothing converged yet.
bool CanSnapFromStart(const SolveRun& run,
                      const StageSummary& stage,
                      double lambda,
                      const StageOutcome& stuck);

// Whether a stage whose path stalled past its start (its step cut back until
// it gave up, `stuck`) can snap from there: under `stable` branching, fewer
// than a few times in a row without a converged step between.
bool CanSnapWhereStalled(const SolveRun& run,
                         const StageSummary& stage,
                         double lambda,
                         int stalled_in_a_row,
                         const StageOutcome& stuck);

// A path that cannot be followed from its last point at `lambda`: the part
// jumps, by energy descent from there, to the rest state a tenth of the
// stage's first increment further on (SnapTrigger::kStalled). A fold of the
// path too sharp to step round is passed so, as a limit point is. On
// failure, `stuck`'s stop with what the minimiser found added.
StageOutcome SnapWhereStalled(SolveRun& run,
                              int index,
                              const StageLoading& loading,
                              const StageOutcome& stuck,
                              double lambda,
                              StageSummary& stage,
                              PathPoint& landed);

// A part that cannot carry the first increment where it starts (a mechanism:
// held at two corners, it swings about the line through them) falls to the
// rest state at that increment's λ. On failure, `stuck`'s stop with what the
// minimiser found added.
StageOutcome SnapFromStart(SolveRun& run,
                           int index,
                           const StageLoading& loading,
                           const StageOutcome& stuck,
                           StageSummary& stage,
                           PathPoint& landed);

}  // namespace drape
