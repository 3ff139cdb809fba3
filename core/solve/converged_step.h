// What becomes of a converged step: contact augmented (the "auto" penalty),
// the state measured (curvature, reactions, probes, contact, layers), contact
// anchors committed, and the step recorded and handed to the observers.
#pragma once

#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/stability_event.h"
#include "core/fe/stage_loading.h"
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
StageOutcome RecordConvergedStep(SolveRun& run,
                                 const StepPlace& place,
                                 const StageLoading& loading,
                                 const ContinuationStep& converged,
                                 const StabilityEvent* classified = nullptr);

// The reaction each support and gripper exerts on the fabric from the
// unbalanced force F_int − F_ext at their nodes (zero for a released gripper,
// whose nodes are free).
std::vector<NamedVector> Reactions(const ShellModel& model,
                                   const std::vector<bool>& released,
                                   const Eigen::VectorXd& unbalanced);

}  // namespace drape
