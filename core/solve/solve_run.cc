#include "core/solve/solve_run.h"

#include <utility>

#include "core/contact/contact_setup.h"

namespace drape {

SolveRun::SolveRun(const Scene& s, ShellModel m, const SolverOptions& o)
    : scene(s),
      options(o),
      model(std::move(m)),
      released(model.grippers.size(), false),
      contact(MakeNodeContact(scene, model)),
      augment_contact(contact && !contact->HasBarrier() &&
                      !(scene.contact && scene.contact->penalty)) {}

DofMap SolveRun::StageDofs() const {
  DofMap d(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) d.FixNode(node, s.fixity);
  for (size_t g = 0; g < model.grippers.size(); ++g)
    if (!released[g])
      for (int node : model.grippers[g].nodes) d.FixNode(node, model.grippers[g].fixity);
  return d;
}

void SolveRun::UseDofs(DofMap stage_dofs) {
  if (dofs && system && *dofs == stage_dofs) return;
  if (system) retired_timers += system->timers();
  system.reset();
  dofs = std::make_unique<DofMap>(std::move(stage_dofs));
  system = std::make_unique<EquilibriumSystem>(model, *dofs, contact.get());
  system->SetSelfContact(self_contact.get());
}

std::vector<HeldGripper> SolveRun::Holds(const Stage& stage) const {
  std::vector<HeldGripper> holds;
  for (size_t g = 0; g < model.grippers.size(); ++g) {
    if (released[g]) continue;
    HeldGripper h;
    h.gripper = &model.grippers[g];
    for (const auto& m : stage.moves)
      if (m.gripper == h.gripper->name) h.path = &m.path;
    for (int node : h.gripper->nodes) {
      h.start_positions.push_back(state.positions.row(node).transpose());
      h.start_rotations.push_back(state.rotations[node]);
    }
    holds.push_back(std::move(h));
  }
  return holds;
}

ArcLengthStepper SolveRun::Stepper(const StageLoading& loading) {
  ArcLengthStepper stepper(*system, loading, Newton(), Psi());
  if (contact && contact->friction() > 0)
    stepper.SetPredictionHook(
        [c = contact.get()](const ShellState& predicted) { return c->LagAtPrediction(predicted); });
  return stepper;
}

NewtonSettings SolveRun::Newton() const {
  NewtonSettings n;
  n.tolerance = options.tolerance;
  n.max_iterations = options.max_iterations;
  n.divergence_ratio = options.divergence_ratio;
  n.stall_correction = options.displacement_tolerance * model.characteristic_length;
  return n;
}

NewtonOutcome SolveRun::SolveAtFixedLambda(double lambda,
                                           const StageLoading& loading,
                                           int max_iterations) {
  NewtonSettings settings = Newton();
  settings.relative_to_force_level = true;
  if (max_iterations > 0) settings.max_iterations = max_iterations;
  return SolveEquilibrium(
      *system,
      [&](const ShellState& s) { return loading.External(lambda, s); },
      settings,
      state,
      cancel);
}

StageOutcome SolveRun::FixedLambdaOutcome(const NewtonOutcome& newton,
                                          StageSummary& stage,
                                          const std::string& failure) {
  CountIterations(newton.iterations, stage);
  if (newton.status == NewtonOutcome::Status::kCancelled)
    return StageOutcome::Cancelled("in stage '" + stage.name + "'");
  if (newton.status != NewtonOutcome::Status::kConverged)
    return StageOutcome::Stop(Termination::kStepTooSmall,
                              "stage '" + stage.name + "' " + failure + ": " + newton.reason);
  return StageOutcome::On();
}

}  // namespace drape
