// What one run of ShellSolver holds while it goes through the stages: the
// model, the state, the system on the stage's DOFs, what the stages have done
// so far, and the record of steps. The stage runners (stage_runner.h) take it
// by reference; nothing outside core/solve sees it.
#pragma once

#include <Eigen/Core>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/contact/node_contact.h"
#include "core/contact/self_contact.h"
#include "core/contact/self_proximity.h"
#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/fe/stage_loading.h"
#include "core/model/scene.h"
#include "core/solve/solve_summary.h"
#include "core/solve/solver_options.h"
#include "core/solve/step_recorder.h"

namespace drape {

// How a stage, or a part of one, ended: the run goes on (kCompleted), or it
// stops, with its termination and why.
struct StageOutcome {
  Termination termination = Termination::kCompleted;
  std::string message;
  // For a cancellation: where it happened ("in stage 'fold' at λ = 0.3"),
  // so that a run stopped by its own deadline can say so instead.
  std::string where;

  bool GoesOn() const { return termination == Termination::kCompleted; }
  static StageOutcome On() { return {}; }
  static StageOutcome Stop(Termination termination, std::string message) {
    return {termination, std::move(message), ""};
  }
  static StageOutcome Cancelled(const std::string& where) {
    return {Termination::kCancelled, "cancelled " + where, where};
  }
};

struct SolveRun {
  SolveRun(const Scene& scene, ShellModel model, const SolverOptions& options);

  // The DOFs a stage solves for: every node free but those the supports and
  // the grippers still held fix.
  DofMap StageDofs() const;
  // Builds the system on `stage_dofs` (kept when they did not change).
  void UseDofs(DofMap stage_dofs);
  // The held grippers of `stage`, each with its path and its nodes' start.
  std::vector<HeldGripper> Holds(const Stage& stage) const;
  // The Newton settings the options ask for on this part.
  NewtonSettings Newton() const;
  // ψ of the arc-length constraint [m].
  double Psi() const { return options.psi > 0 ? options.psi : model.characteristic_length; }
  // A stepper for this run's system: its Newton settings and ψ, friction
  // lagged at each predicted state.
  ArcLengthStepper Stepper(const StageLoading& loading);
  // Newton at a fixed λ from the present state, judged against the force
  // level (no load is added): a hold, a settle pass, an augmentation pass.
  // `max_iterations` > 0 overrides the options' limit.
  NewtonOutcome SolveAtFixedLambda(double lambda,
                                   const StageLoading& loading,
                                   int max_iterations = 0);
  // Counts a fixed-λ solve's iterations in the stage; how the stage goes on:
  // a stop when it was cancelled or did not converge (`failure` says what the
  // stage did not do).
  StageOutcome FixedLambdaOutcome(const NewtonOutcome& newton,
                                  StageSummary& stage,
                                  const std::string& failure);
  // Counts `iterations` in the stage and the run.
  void CountIterations(int iterations, StageSummary& stage) {
    stage.iterations += iterations;
    summary.iterations += iterations;
  }

  Scene scene;
  SolverOptions options;
  ShellModel model;
  std::vector<bool> released;            // per gripper
  std::unique_ptr<NodeContact> contact;  // null without obstacles
  // "auto" penalty: penetration held to options.penetration_tolerance by
  // augmented-Lagrangian passes. A penalty the user set is used as given.
  bool augment_contact = false;
  // The last converged step had every node in contact sliding and nothing
  // but the stabilisation springs holding the part: it is not at rest.
  bool slides_as_a_whole = false;
  // The DOF map of the current stage, and the system built on it.
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<EquilibriumSystem> system;
  SystemTimers retired_timers;  // of systems replaced when a release changed the DOFs
  ShellState state;
  double weight_done = 0;  // weight factor reached by earlier stages
  double loads_done = 0;   // point-load factor reached by earlier stages
  // The token the run checks: the caller's, and the run's deadline.
  CancellationToken run_token;
  const CancellationToken* cancel = nullptr;
  SolveSummary summary;
  std::chrono::steady_clock::time_point start;
  // Finds where the fabric's own parts come close (layers of a fold).
  std::unique_ptr<SelfProximity> layers;
  // Keeps them apart (scene contact.self), null otherwise.
  std::unique_ptr<SelfContact> self_contact;
  // Numbers the converged steps and hands them to the observers.
  std::unique_ptr<StepRecorder> recorder;
  // +1 while λ rises along the stage's path, −1 after a limit point turned it.
  int lambda_direction = 1;
  double stage_path_length = 0;         // Σ arc lengths accepted in the stage [m]
  double last_stabilization_force = 0;  // of the last converged step [N]
  // The mean element edge [m]: how far a nodal rotation moves its neighbours.
  double element_size = 0;
  // The reference surface's offsets from the flat plane (free DOFs at use):
  // decides the sign of a critical mode where both signs are stable.
  Eigen::VectorXd imperfection;
};

}  // namespace drape
