// Contact passes at a converged step: with the "auto" penalty each pass
// moves the multipliers by the penalty force (augmented Lagrangian), with
// friction it re-lags the normal forces and tangent planes, and solves again
// at the same λ, until the deepest node is within
// options.penetration_tolerance of the thickness and friction's lag has
// stopped changing, or options.max_augmentations passes are done.
#pragma once

#include <string>

#include "core/continuation/arc_length_stepper.h"
#include "core/fe/stage_loading.h"
#include "core/solve/solve_run.h"

namespace drape {

struct Augmentation {
  int passes = 0;
  std::string shortfall;  // why it stopped short of the target ("" when met)
};

// The passes' iterations go into `step` (and the run's count). A pass that
// does not converge is undone, multipliers and all, and the system
// reassembled at the state kept, so the step's reactions are those of that
// state.
Augmentation AugmentContact(SolveRun& run,
                            double lambda,
                            const StageLoading& loading,
                            ContinuationStep& step);

}  // namespace drape
