// What the solver is asked to do (Ceres' Solver::Options): every field has its
// default where it is declared, and IsValid names the field that is wrong.
#pragma once

#include <string>

#include "core/continuation/step_policy.h"
#include "core/model/scene.h"

namespace drape {

struct SolverOptions {
  // Equilibrium: ‖R‖/‖R₀‖ at most this, R₀ the out-of-balance force the step
  // added (or the force level, when it adds none); or ‖R‖ at the round-off
  // floor (NewtonSettings::round_off_factor).
  double tolerance = 1e-5;
  // Stall: a Newton correction at most this fraction of the part's size while
  // the residual is above the tolerance and no longer halves fails the step
  // (it is cut back). Never a convergence test.
  double displacement_tolerance = 1e-8;
  // N_p, the iterations a step should take; γ = N_p / N_{n−1} scales the next step.
  int target_iterations = 7;
  // Scale steps by γ (the paper's acceleration); off keeps Δλ₀ (cut-backs aside).
  bool acceleration = true;
  // Bounds on γ per step: no step grows or shrinks faster than this.
  double min_step_growth = 0.25;
  double max_step_growth = 4.0;
  // Largest load-factor step of a stage (arc-length: the largest Δs, measured
  // as the Δλ it gives in the stage's first, linear step).
  double max_increment = 0.25;
  // Steps over the whole run; a run that needs more stops with kMaxStepsReached.
  int max_steps = 5000;
  // Newton iterations per step before the step is cut back.
  int max_iterations = 30;
  // Successive cut-backs (halving) of one step before the stage fails.
  int max_step_cuts = 10;
  // Limit points one stage's path may pass before it fails (kStepTooSmall).
  int max_turns = 20;
  // ‖R‖/‖R₀‖ above this in any iteration counts as divergence (cut back).
  double divergence_ratio = 1e6;
  // ψ [m]: weight of λ against lengths in the arc-length constraint; 0 uses
  // the part's characteristic length (its diagonal).
  double psi = 0;
  // Contact with the "auto" penalty: augmented-Lagrangian passes after each
  // converged step until the deepest node is within this fraction of the
  // thickness, at most `max_augmentations` passes of at most
  // `max_augmentation_iterations` Newton iterations each (0: max_iterations).
  // A step that stops short says so (ContactReport::augmentation_shortfall).
  double penetration_tolerance = 0.005;
  int max_augmentations = 8;
  int max_augmentation_iterations = 0;
  // At a bifurcation: switch to the branch a real part takes (kStable) or
  // follow the primary path (kFundamental, the paper's behaviour).
  Branching branching = Branching::kStable;
  // > 1: mesh sequencing (core/solve/mesh_sequencing.h) with this factor;
  // kAutoSequencing: the solver chooses (AutoSequencing).
  int sequencing = 1;
  bool sequencing_auto = false;  // set by the solver: `sequencing` was chosen by auto
  // Threads for element assembly; 0 uses OpenMP's default.
  int threads = 0;
  // Wall-clock limit of a run [s], pauses included; 0: none. Past it the run
  // stops with Termination::kTimeLimit and keeps every converged step.
  double max_wall_s = 0;

  // The step-length rule these options ask for.
  StepPolicy Stepping() const {
    return {acceleration, target_iterations, min_step_growth, max_step_growth};
  }

  // Copies the scene's `solver` settings over the defaults.
  static SolverOptions FromScene(const SolverSettings& settings);

  // False, with `error` naming the field, its value and the broken constraint.
  bool IsValid(std::string* error) const;
};

}  // namespace drape
