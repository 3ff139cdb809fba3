// Limit and bifurcation points met along a stage's path: what a change of the
// negative pivots was, whether the run switches branch there, and the switch
// itself (locate, switch, record the points reached).
#pragma once

#include <optional>

#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/branch_switch.h"
#include "core/continuation/stability_event.h"
#include "core/fe/stage_loading.h"
#include "core/solve/contact_augmentation.h"
#include "core/solve/solve_run.h"

namespace drape {

// What a change of the negative pivots at a converged step at `lambda` is: a
// limit point when λ's direction along the path (+1 rising, −1 falling) is
// not the one before, else a bifurcation.
StabilityEvent ClassifyPivotChange(int direction_before, int direction, double lambda);

// The change of the negative pivots at a converged step, if its count differs
// from the last recorded step's: classified against λ's direction along the
// path before it, `direction`, which then becomes the direction at the step.
std::optional<StabilityEvent> PivotChange(const SolveRun& run,
                                          ArcLengthStepper& stepper,
                                          const ContinuationStep& step,
                                          int& direction);

// Whether `step` left a stable state under `stable` branching: the last
// recorded step had 0 negative pivots, this one has some. Where that is a
// bifurcation the run switches branch (SwitchesAt); a limit point, it snaps
// (SnapsAt).
bool LosesStability(const SolveRun& run, const ContinuationStep& step);

// Whether the run switches branch at this event: a bifurcation crossed from
// a stable state under `stable` branching. Between a limit point and the next
// one the path is unstable already (a real part snaps through it), and the
// branches of a bifurcation there are no more observable than the primary
// path, which leads on to the stable states beyond.
bool SwitchesAt(const SolveRun& run, const StabilityEvent& event, const ContinuationStep& step);

// Where a path meets a bifurcation: the last converged point before it, the
// direction it came from (null at a stage's start) and the point past it.
struct Crossing {
  PathPoint start;
  const PathDirection* previous = nullptr;
  PathPoint past;
};

// How the run locates a critical point and steps along its modes: the
// bracket to kLocateFraction of the stage's path, the switch's amplitude, the
// scene's imperfection.
BifurcationSettings PassageSettings(const SolveRun& run);

// Records a point a passage reached as the stage's next step; `passes` as
// for RecordConvergedStep.
StageOutcome RecordPathPoint(SolveRun& run,
                             int index,
                             const StageLoading& loading,
                             const PathPoint& point,
                             StageSummary& stage,
                             const StabilityEvent* event = nullptr,
                             const Augmentation* passes = nullptr);

// Locates the bifurcation, switches to a secondary branch and records the
// points reached (the bifurcation, the first point on the branch) into
// `reached`; the stepping goes on from there. Where no branch can be
// followed the part snaps (snap_passage.h) and `reached` is where it landed;
// a stop when it finds no rest state (kNoStableBranch) or the run was
// cancelled.
StageOutcome PassBifurcation(SolveRun& run,
                             int index,
                             const StageLoading& loading,
                             ArcLengthStepper& stepper,
                             const Crossing& crossing,
                             StabilityEvent event,
                             StageSummary& stage,
                             PathPoint& reached);

}  // namespace drape
