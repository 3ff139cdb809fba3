// What a run says about itself when a stage cannot go on or ends somewhere a
// user should know of: the causes to look at and the keys to change, built as
// whole strings.
#pragma once

#include <string>

#include "core/solve/solve_run.h"

namespace drape {

// What a user can change when a stage cannot take its next step.
std::string WhatToChange(const SolveRun& run, const Stage& spec, const StageSummary& stage);

// Nothing holds the part but frictionless contact (no support, no gripper:
// the contact's stabilisation springs are on): it may have no stable rest.
bool HeldOnlyByFrictionlessContact(const SolveRun& run);

// Causes that lie in the contact settings ("" when none applies): a part held
// by nothing but frictionless contact, a penalty far above the automatic one.
std::string ContactHint(const SolveRun& run);

// A stage ending on a tangent with negative pivots: a real part would not
// rest there.
std::string UnstableEndWarning(const Stage& spec,
                               int step,
                               int negative_pivots,
                               Branching branching);

// A stage whose path reached λ = 1 only after running back below 0: its end
// is reached by a jump.
std::string ReversedLoadWarning(const Stage& spec, double lowest_lambda);

// Stabilisation springs still carrying force after the settle passes.
std::string UnsettledNote(const std::string& stage_name,
                          double spring_force,
                          double weight,
                          int passes);

// The run's closing warnings: layers that passed into each other, contact
// short of its penetration target. Appended to run.summary.warnings.
void AddEndOfRunWarnings(SolveRun& run);

// The run's final word: `outcome` as the summary says it, a cancellation by
// the run's own deadline told as the time limit it is.
void Conclude(SolveRun& run, const StageOutcome& outcome);

}  // namespace drape
