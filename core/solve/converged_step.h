// What becomes of a converged step: contact augmented (the "auto" penalty),
// the state measured (curvature, reactions, probes, contact, layers), contact
// anchors committed, and the step recorded and handed to the observers.
#pragma once

#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/stability_event.h"
#include "core/fe/stage_loading.h"
#include "core/solve/contact_augmentation.h"
#include "core/solve/solve_run.h"

namespace drape {

// Where on the run a step lands.
struct StepPlace {
  int stage = -1;      // index in the scene's stages
  int stage_step = 0;  // 1-based within the stage
  double lambda = 0;   // the stage's load factor
};

// Records the step converged at run.state. The run stops when the state is
// not finite (no observer and no file ever sees one) or an observer asks.
// `classified`: what a change of the negative pivots at this step was (see
// StepRecorder::Record).
// `passes`: the contact passes already made at this state (PassContact);
// null: they are made here.
StageOutcome RecordConvergedStep(SolveRun& run,
                                 const StepPlace& place,
                                 const StageLoading& loading,
                                 const ContinuationStep& converged,
                                 const StabilityEvent* classified = nullptr,
                                 const Augmentation* passes = nullptr);

// The contact passes (contact_augmentation.h) at a step converged at λ,
// before the path judges it. False, with the contact's lags and
// multipliers as they were, when friction's lag did not settle (a node's
// normal force still 1 % off the one its friction was solved with: the step
// went past where friction holds, or too far): the caller cuts the step.
bool PassContact(SolveRun& run,
                 double lambda,
                 const StageLoading& loading,
                 ContinuationStep& step,
                 Augmentation& passes);

// The reaction each support and gripper exerts on the fabric from the
// unbalanced force F_int − F_ext at their nodes (zero for a released gripper,
// whose nodes are free).
std::vector<NamedVector> Reactions(const ShellModel& model,
                                   const std::vector<bool>& released,
                                   const Eigen::VectorXd& unbalanced);

}  // namespace drape
