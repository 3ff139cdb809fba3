#include "core/solve/stage_runner.h"

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "core/contact/contact_setup.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/well_posedness.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

// Contact stabilisation springs (node_contact.h) only where contact alone
// must hold the fabric: this fraction of the membrane stiffness per node
// keeps such a pivot well above the zero-pivot bound while its force stays
// small.
constexpr double kStabilization = 1e-8;

void SetStabilization(SolveRun& run, const DofMap& stage_dofs) {
  const ShellModel& model = run.model;
  const bool needed = !HoldsRestrainRigidMotion(model, stage_dofs);
  std::vector<bool> held(model.NodeCount());
  for (int i = 0; i < model.NodeCount(); ++i) held[i] = stage_dofs.IsFixed(kDofsPerNode * i);
  run.contact->SetStabilization(
      needed ? kStabilization * model.section.membrane.diagonal().maxCoeff() : 0.0,
      std::move(held));
}

// The obstacles stage `spec` moves, each with its path and where it starts.
std::vector<MovedObstacle> MovedObstacles(const SolveRun& run, const Stage& spec) {
  std::vector<MovedObstacle> moved;
  for (const auto& move : spec.moves)
    for (size_t o = 0; o < run.scene.obstacles.size(); ++o)
      if (!move.obstacle.empty() && run.scene.obstacles[o].name == move.obstacle)
        moved.push_back({static_cast<int>(o), &move.path, run.state.obstacles.at(o)});
  return moved;
}

// The stage's kind of run, and the settle passes after it.
StageOutcome RunStageOn(SolveRun& run,
                        int index,
                        const StageLoading& loading,
                        StageSummary& stage) {
  const Stage& spec = run.scene.stages[index];
  StageOutcome outcome;
  if (spec.kind == StageKind::kHold)
    outcome = RunHold(run, index, loading, stage);
  else if (run.options.sequencing > 1)
    outcome = RunSequenced(run, index, loading, stage);
  else
    outcome = RunPath(run, index, loading, stage);
  if (outcome.GoesOn() && run.contact && run.contact->stabilization() > 0)
    outcome = Settle(run, index, loading, stage);
  return outcome;
}

}  // namespace

ContinuationStep StepOf(const NewtonOutcome& newton) {
  ContinuationStep step;
  step.iterations = newton.iterations;
  step.residuals = newton.residuals;
  step.convergence = newton.convergence;
  step.negative_pivots = newton.negative_pivots;
  return step;
}

StageOutcome MaxStepsReached(const SolveRun& run, const Stage& spec, double lambda) {
  return StageOutcome::Stop(
      Termination::kMaxStepsReached,
      "stage '" + spec.name + "' needed more than " + std::to_string(run.options.max_steps) +
          " steps (solver.max_steps) and stopped at λ = " + std::to_string(lambda));
}

StageOutcome CutBack(SolveRun& run,
                     const ContinuationStep& step,
                     const Stage& spec,
                     double lambda,
                     int& cuts_in_a_row,
                     StageSummary& stage) {
  if (step.status == NewtonOutcome::Status::kCancelled)
    return StageOutcome::Cancelled("in stage '" + spec.name + "' at λ = " + std::to_string(lambda));
  if (cuts_in_a_row == run.options.max_step_cuts)
    return StageOutcome::Stop(Termination::kStepTooSmall,
                              "stage '" + spec.name + "' stopped at λ = " + std::to_string(lambda) +
                                  " after " + std::to_string(cuts_in_a_row) + " cut-backs: " +
                                  step.reason + "; " + WhatToChange(run, spec, stage));
  // Cut back and retry: counted only when it happens.
  ++cuts_in_a_row;
  ++stage.step_cuts;
  ++run.summary.step_cuts;
  return StageOutcome::On();
}

StageOutcome RunPath(SolveRun& run, int index, const StageLoading& loading, StageSummary& stage) {
  return run.scene.stages[index].control == StepControl::kLoad
             ? RunLoadControl(run, index, loading, stage)
             : RunArcLength(run, index, loading, stage);
}

StageOutcome RunStage(SolveRun& run, int index) {
  const Stage& spec = run.scene.stages[index];
  StageSummary stage;
  stage.name = spec.name;
  stage.kind = spec.kind;
  stage.control_given = spec.control;
  stage.control_used = spec.kind == StageKind::kHold ? StepControl::kLoad : spec.control;
  const auto stage_start = Clock::now();
  struct Finish {
    SolveSummary& summary;
    StageSummary& stage;
    Clock::time_point start;
    ~Finish() {
      stage.time_s = std::chrono::duration<double>(Clock::now() - start).count();
      summary.stages.push_back(stage);
    }
  } finish{run.summary, stage, stage_start};

  for (const auto& name : spec.release)
    for (size_t g = 0; g < run.model.grippers.size(); ++g)
      if (run.model.grippers[g].name == name) run.released[g] = true;
  DofMap stage_dofs = run.StageDofs();
  if (run.contact) SetStabilization(run, stage_dofs);
  if (!run.contact && stage_dofs.FreeCount() == stage_dofs.DofCount())
    return StageOutcome::Stop(
        Termination::kIllPosed,
        "stage '" + spec.name + "': nothing holds the fabric (every support and gripper is " +
            "released), so it would move as a rigid body; keep a support or a gripper");
  run.UseDofs(std::move(stage_dofs));
  const StageLoading loading(
      run.model, spec, run.Holds(spec), run.weight_done, run.loads_done, MovedObstacles(run, spec));
  if (run.contact)
    if (const std::string problem = GripperDrivenIntoObstacle(
            run.scene, index, run.model, run.released, *run.contact, loading, run.state);
        !problem.empty())
      return StageOutcome::Stop(Termination::kIllPosed, problem);
  run.lambda_direction = 1;
  run.stage_path_length = 0;

  const StageOutcome outcome = RunStageOn(run, index, loading, stage);
  if (!outcome.GoesOn()) return outcome;
  const int pivots = run.recorder->last_negative_pivots();
  run.summary.final_negative_pivots = pivots;
  if (pivots > 0)
    run.summary.warnings.push_back(
        UnstableEndWarning(spec, run.summary.steps, pivots, run.options.branching));
  run.weight_done = loading.WeightFactor(1.0);
  run.loads_done = loading.LoadFactor(1.0);
  return outcome;
}

}  // namespace drape
