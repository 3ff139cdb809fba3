// What happened in a run (Ceres' Solver::Summary): why it stopped, what each
// stage did, where the time went. Fields start at sentinels so an unfilled
// one is obvious.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/model/scene.h"
#include "core/solve/step_state.h"

namespace drape {

enum class Termination {
  kNotRun,             // Solve was not called
  kCompleted,          // every stage reached λ = 1
  kStepTooSmall,       // a step was cut back max_step_cuts times and still failed
  kMaxStepsReached,    // the run needed more than max_steps steps
  kCancelled,          // the cancellation token was set
  kStoppedByObserver,  // an observer returned kStop
  kInvalidInput,       // options or scene rejected before any work
  kIllPosed,           // a stage cannot be solved as posed (e.g. nothing holds the fabric)
  kNumericalFailure,   // the linear algebra failed (e.g. out of memory in the factorisation)
  kNoStableBranch,     // a bifurcation was crossed and no secondary branch could be followed
  kUnheld,             // the part would jump, and nothing holds it: it slides or falls away
  kTimeLimit,          // the run took longer than SolverOptions::max_wall_s
};

const char* ToString(Termination termination);

// One line: what happened, where, and which way the path went on.
std::string Describe(const StabilityEvent& event);

struct StageSummary {
  std::string name;
  StageKind kind = StageKind::kGravity;
  StepControl control_given = StepControl::kArcLength;
  StepControl control_used = StepControl::kLoad;
  int steps = 0;
  int iterations = 0;
  int step_cuts = 0;
  double final_lambda = 0;
  double time_s = 0;
};

struct SolveSummary {
  Termination termination = Termination::kNotRun;
  std::string message = "Solve was not called";

  int nodes = -1, elements = -1, dofs = -1, free_dofs = -1;
  int threads_used = -1;
  int steps = 0;
  int iterations = 0;
  int step_cuts = 0;
  int factorizations = 0;
  int indefinite_factorizations = 0;  // tangents that were not positive definite
  int reused_factorizations = 0;      // requests for a tangent already factorised
  std::vector<StageSummary> stages;
  std::vector<StabilityEvent> stability_events;
  std::vector<std::string> notes;     // what was used instead of what was asked, and why
  std::vector<std::string> warnings;  // about the scene (e.g. a softening bending law) and
                                      // about the result (a stage ending on an unstable state)
  // Negative pivots of the tangent at the last stage's end: 0 is a state a
  // real part rests in; more, and the report says the run converged to an
  // unstable equilibrium rather than just "converged".
  int final_negative_pivots = 0;

  // Bending: the largest principal curvature reached in any converged step,
  // against the range the bending laws were measured or fitted over (∞ when
  // every law is linear) [1/m].
  double max_curvature = 0;
  // The largest curvature the laws were evaluated at (their argument K,
  // MaxLawCurvature): this, not the principal curvature, is held against
  // their range [1/m].
  double max_law_curvature = 0;
  double bending_valid_to = std::numeric_limits<double>::infinity();

  // Layers of the fabric on each other (StepState::layer_distance): the
  // closest over the run (∞ when no two parts came within twice the
  // thickness), its step, and which parts count as distinct [m].
  double min_layer_distance = std::numeric_limits<double>::infinity();
  int min_layer_step = 0;
  double layer_exclusion = 0;

  // Contact (scenes with obstacles; zero otherwise).
  double contact_penalty = 0;          // k per area used [N/m³]
  double max_penetration = 0;          // over every converged step [m]
  double max_stabilization_force = 0;  // largest nodal spring force, any step [N]
  int augmentations = 0;               // augmented-Lagrangian passes (each one Newton solve)
  // Steps whose augmentation stopped short of its penetration target, and
  // the deepest of them (also a warning).
  int penetration_target_missed = 0;
  double worst_missed_penetration = 0;  // [m]
  int worst_missed_step = 0;
  std::string worst_missed_reason;
  // Steps whose friction lag still moved after the contact passes (no
  // penetration target missed): how many, the first, and why.
  int friction_unsettled = 0;
  int first_unsettled_step = 0;
  std::string unsettled_reason;
  int branch_switches = 0;  // bifurcations passed onto a secondary branch

  double total_s = 0;
  double assembly_s = 0;
  double factorization_s = 0;
  double solve_s = 0;
  double observer_s = 0;
  double peak_memory_bytes = 0;  // the process's peak resident memory when the run ended

  bool IsComplete() const { return termination == Termination::kCompleted; }
  std::string BriefReport() const;  // one line
  std::string FullReport() const;   // a table: sizes, stages, times, termination
};

}  // namespace drape
