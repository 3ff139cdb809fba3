#include "core/solve/run_diagnostics.h"

#include "core/contact/contact_setup.h"
#include "core/model/string_format.h"

namespace drape {

bool HeldOnlyByFrictionlessContact(const SolveRun& run) {
  return run.contact && run.contact->stabilization() > 0 && run.contact->friction() == 0;
}

std::string ContactHint(const SolveRun& run) {
  if (!run.contact) return "";
  std::string hint;
  if (HeldOnlyByFrictionlessContact(run))
    // A hanging part slides off a frictionless form the way a chain runs off
    // a pulley: no stable rest exists for the path to reach.
    hint +=
        ". Nothing but frictionless contact holds the part (no support, no gripper): it can "
        "slide off the obstacle, so it may have no stable rest; give contact.friction, or "
        "hold it with a support";
  const double automatic = AutoPenalty(run.model);
  if (run.scene.contact && run.scene.contact->penalty && run.contact->penalty() > 3 * automatic)
    hint += Format(
        ". contact.penalty %.3g N/m³ is %.0f times the automatic one (E h / ℓ² = %.3g): "
        "so stiff a contact switches on and off abruptly; \"auto\" adapts it",
        run.contact->penalty(),
        run.contact->penalty() / automatic,
        automatic);
  return hint;
}

std::string WhatToChange(const SolveRun& run, const Stage& spec, const StageSummary& stage) {
  const std::string key = "stages[" + std::to_string(&spec - run.scene.stages.data()) + "]";
  if (stage.steps == 0)
    // Not even the smallest first step converged: the tangent at the start
    // barely resists the load (no bending, nothing holding the part) or the
    // load is far beyond it.
    return "not even a first step 2^" + std::to_string(run.options.max_step_cuts) +
           " times smaller than " + key +
           ".initial_increment converged: the part barely resists "
           "its load where it starts (material.bending, supports, grippers)" +
           ContactHint(run);
  return "the path turns or stiffens sharply here (contact, a snap, a fold): allow more "
         "cut-backs (solver.max_step_cuts), more iterations (solver.max_iterations), or the "
         "other solver.branching" +
         ContactHint(run);
}

std::string UnstableEndWarning(const Stage& spec,
                               int step,
                               int negative_pivots,
                               Branching branching) {
  // Only with `fundamental` branching, past a limit point, or on a branch
  // that is itself unstable: say so rather than let it pass as converged.
  return Format(
      "stage '%s' ends at step %d on an unstable equilibrium: its tangent has %d "
      "negative pivot%s (a real part would not rest there)%s",
      spec.name.c_str(),
      step,
      negative_pivots,
      negative_pivots == 1 ? "" : "s",
      branching == Branching::kFundamental ? "; solver.branching is fundamental" : "");
}

std::string ReversedLoadWarning(const Stage& spec, double lowest_lambda) {
  // The end is an equilibrium, but the path to it needed the load reversed:
  // going forward, a real part jumps there instead.
  return Format(
      "stage '%s' reached λ = 1 only after its path ran back to λ = %.3g (the load "
      "reversed): past a limit point the part would snap, and its end state is "
      "reached by a jump no quasi-static path makes",
      spec.name.c_str(),
      lowest_lambda);
}

std::string UnsettledNote(const std::string& stage_name,
                          double spring_force,
                          double weight,
                          int passes) {
  return Format(
      "stage '%s' ends with stabilisation springs still carrying up to %.3g N per "
      "node (%.2g of the weight) after %d settle steps",
      stage_name.c_str(),
      spring_force,
      spring_force / weight,
      passes);
}

void AddEndOfRunWarnings(SolveRun& run) {
  SolveSummary& s = run.summary;
  const double thickness = run.model.thickness;
  if (s.min_layer_distance < (run.self_contact ? run.self_contact->settings().offset : thickness))
    s.warnings.push_back(
        Format("the fabric passes into itself: at step %d two of its parts (more than %.3g m "
               "apart at rest) are %.3g m apart, %.2f of its thickness%s",
               s.min_layer_step,
               s.layer_exclusion,
               s.min_layer_distance,
               s.min_layer_distance / thickness,
               run.self_contact ? " (closer than contact.thickness: held there by a gripper?)"
                                : "; contact.self keeps layers apart"));
  if (s.penetration_target_missed > 0)
    s.warnings.push_back(
        Format("contact: the penetration target (%.3g %% of the thickness, %.3g m) was not "
               "reached in %d step%s; the deepest, %.3g m (%.2g %% of the thickness) at step "
               "%d: %s",
               100 * run.options.penetration_tolerance,
               run.options.penetration_tolerance * thickness,
               s.penetration_target_missed,
               s.penetration_target_missed == 1 ? "" : "s",
               s.worst_missed_penetration,
               100 * s.worst_missed_penetration / thickness,
               s.worst_missed_step,
               s.worst_missed_reason.c_str()));
  if (s.friction_unsettled > 0)
    s.warnings.push_back(
        Format("contact: friction's normal forces had not settled in %d step%s "
               "(the first, step %d: %s)",
               s.friction_unsettled,
               s.friction_unsettled == 1 ? "" : "s",
               s.first_unsettled_step,
               s.unsettled_reason.c_str()));
}

void Conclude(SolveRun& run, const StageOutcome& outcome) {
  run.summary.termination = outcome.termination;
  run.summary.message = outcome.message;
  if (outcome.termination == Termination::kCancelled && run.run_token.DeadlinePassed()) {
    // Stopped by the run's own deadline, not by the user.
    run.summary.termination = Termination::kTimeLimit;
    run.summary.message = Format(
                              "the run reached its time limit of %g s (solver.max_wall_s, drape "
                              "run --time-limit): ",
                              run.options.max_wall_s) +
                          outcome.where;
  }
}

}  // namespace drape
