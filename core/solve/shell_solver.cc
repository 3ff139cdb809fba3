#include "core/solve/shell_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/contact/contact_setup.h"
#include "core/contact/node_contact.h"
#include "core/contact/self_proximity.h"
#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/branch_switch.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_solver.h"
#include "core/fe/dof_map.h"
#include "core/fe/element_fields.h"
#include "core/fe/stage_loading.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/solve/gripper_drag.h"
#include "core/solve/mesh_sequencing.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kStabilization = 1e-8;  // of the membrane stiffness, per node
constexpr int kMaxSettlePasses = 5;
// Locating a bifurcation: the bracket's arc length at most this fraction of
// the stage's path up to it (λ_c to about 0.1 % where λ dominates Δs).
constexpr double kLocateFraction = 1e-3;
// The step onto a secondary branch: this fraction of the part's diagonal
// along the critical mode (0.2 mm on a 20 cm strip). Small enough to start
// the branch near the point, large enough that the branch's tangent is
// definite by more than round-off.
constexpr double kSwitchAmplitude = 1e-3;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string Name(const std::string& kind, const std::string& name) {
  return kind + " '" + name + "'";
}

// A node can be held by one thing at a time: a support, or a gripper. Two
// holders of one node are fine while neither moves; a moving gripper must own
// its nodes alone, or the node would have to be in two places.
void CheckHoldsDoNotConflict(const Scene& scene, const ShellModel& model) {
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    const Stage& stage = scene.stages[s];
    std::map<int, std::string> holder;  // node → who holds it still in this stage
    for (const auto& support : model.supports)
      for (int node : support.nodes) holder.emplace(node, Name("support", support.name));
    std::map<int, std::string> mover;
    for (size_t m = 0; m < stage.moves.size(); ++m) {
      const std::string path = "stages[" + std::to_string(s) + "].moves[" + std::to_string(m) + "]";
      for (const auto& g : model.grippers) {
        if (g.name != stage.moves[m].gripper) continue;
        for (int node : g.nodes) {
          if (auto it = holder.find(node); it != holder.end())
            throw SceneError(path,
                             Name("gripper", g.name) + " would move node " + std::to_string(node) +
                                 ", which " + it->second +
                                 " holds in place: it cannot be in two places");
          if (auto it = mover.find(node); it != mover.end())
            throw SceneError(path,
                             Name("gripper", g.name) + " and " + it->second + " both move node " +
                                 std::to_string(node) + " along different paths");
          mover.emplace(node, Name("gripper", g.name));
        }
      }
    }
    for (const auto& g : model.grippers) {
      const bool moved = std::any_of(stage.moves.begin(), stage.moves.end(), [&](const Move& m) {
        return m.gripper == g.name;
      });
      if (moved) continue;
      for (int node : g.nodes)
        if (auto it = mover.find(node); it != mover.end())
          throw SceneError("stages[" + std::to_string(s) + "]",
                           it->second + " moves node " + std::to_string(node) + ", which " +
                               Name("gripper", g.name) +
                               " holds in place: it cannot be in two places");
    }
  }
}

}  // namespace

struct ShellSolver::Impl {
  Impl(const Scene& s, ShellModel m, const SolverOptions& o)
      : scene(s),
        options(o),
        model(std::move(m)),
        released(model.grippers.size(), false),
        contact(MakeNodeContact(scene, model)),
        augment_contact(contact && !(scene.contact && scene.contact->penalty)) {}

  DofMap StageDofs() const;
  void UseDofs(DofMap stage_dofs);
  std::vector<HeldGripper> Holds(const Stage& stage) const;
  NewtonSettings Newton() const;
  double Psi() const { return options.psi > 0 ? options.psi : model.characteristic_length; }

  // Each runs one stage; false when the run must stop (the summary says why).
  bool RunStage(int index);
  bool RunHold(int index, const StageLoading& loading, StageSummary& stage);
  // Newton at a fixed λ from the present state, judged against the force
  // level (no load is added): a hold, a settle pass, an augmentation pass.
  // `max_iterations` > 0 overrides the options' limit.
  NewtonOutcome SolveAtFixedLambda(double lambda,
                                   const StageLoading& loading,
                                   int max_iterations = 0);
  // Counts such a solve in the stage; false (and the run stopped, saying
  // `failure` and why) when it was cancelled or did not converge.
  bool Accept(const NewtonOutcome& newton, StageSummary& stage, const std::string& failure);
  bool RunLoadControl(int index, const StageLoading& loading, StageSummary& stage);
  bool RunArcLength(int index, const StageLoading& loading, StageSummary& stage);
  // The stage's path on the coarsened mesh, then Newton on this one from its
  // interpolated end (mesh_sequencing.h). Falls back to the path on this
  // mesh, with a note, when the coarse run fails or the end is not stable.
  bool RunSequenced(int index, const StageLoading& loading, StageSummary& stage);
  bool RunPath(int index, const StageLoading& loading, StageSummary& stage) {
    return scene.stages[index].control == StepControl::kLoad ? RunLoadControl(index, loading, stage)
                                                             : RunArcLength(index, loading, stage);
  }
  // Re-solves at the stage's end, springs re-anchored, until their force is
  // negligible: the stage then ends in the equilibrium without them.
  bool Settle(int index, const StageLoading& loading, StageSummary& stage);
  // False (and the run stopped, naming the gripper, the obstacle and the
  // key) when the stage's motion puts a held node deeper than the thickness
  // into an obstacle: no equilibrium exists there, and the path would only
  // find that out after many cut-backs.
  bool GrippersStayOutside(int index, const StageLoading& loading);
  // What a user can change when a stage cannot take its next step.
  std::string WhatToChange(const Stage& spec, const StageSummary& stage) const;
  // Causes that lie in the contact settings ("" when none applies): a part
  // held by nothing but frictionless contact, a penalty far above the
  // automatic one.
  std::string ContactHint() const;
  // Shared bookkeeping of a failed step: true to retry smaller, false to stop.
  bool RetryAfterFailure(const ContinuationStep& step,
                         const Stage& spec,
                         double lambda,
                         int& cuts_in_a_row,
                         StageSummary& stage);

  // Hands a converged step to the observers. A change of the negative
  // pivots is recorded as a stability event: `classified` says what it was
  // (null: a change at fixed λ or under load control, kept as a bifurcation
  // followed on the primary path).
  bool Emit(int stage_index,
            int stage_step,
            double lambda,
            const StageLoading& loading,
            const ContinuationStep& step,
            const StabilityEvent* classified = nullptr);
  // What a change of the count at a converged step is: a limit point when
  // λ's direction along the path flipped, else a bifurcation.
  StabilityEvent Classify(ArcLengthStepper& stepper, const ContinuationStep& step);
  // Whether the run switches branch at this event: a bifurcation crossed
  // from a stable state under `stable` branching. Between a limit point and
  // the next one the path is unstable already (a real part snaps through
  // it), and the branches of a bifurcation there are no more observable than
  // the primary path, which leads on to the stable states beyond.
  bool SwitchesAt(const StabilityEvent& event, const ContinuationStep& step) const {
    return event.kind == StabilityKind::kBifurcation && last_negative_pivots == 0 &&
           step.negative_pivots > 0 && options.branching == Branching::kStable;
  }
  // At a bifurcation under `stable` branching: locates it, switches to a
  // secondary branch and emits the points reached (the bifurcation, the
  // first point on the branch); the stepping goes on from there. False when
  // the run must stop (no branch: kNoStableBranch; cancelled).
  bool PassBifurcation(int index,
                       const StageLoading& loading,
                       ArcLengthStepper& stepper,
                       const PathPoint& start,
                       const PathDirection* previous,
                       const PathPoint& crossing,
                       StabilityEvent event,
                       StageSummary& stage,
                       PathPoint& reached);
  // Augmented-Lagrangian passes at a converged step until the penetration is
  // within options.penetration_tolerance of the thickness (or
  // options.max_augmentations passes).
  // Returns why it stopped short ("" when the target was met); a pass that
  // did not converge is undone, and the system reassembled at the state kept.
  struct Augmentation {
    int passes = 0;
    std::string shortfall;
  };
  Augmentation Augment(double lambda, const StageLoading& loading, ContinuationStep& step);
  void StopAtMaxSteps(const Stage& spec, double lambda) {
    Stop(Termination::kMaxStepsReached,
         "stage '" + spec.name + "' needed more than " + std::to_string(options.max_steps) +
             " steps (solver.max_steps) and stopped at λ = " + std::to_string(lambda));
  }
  void Stop(Termination t, std::string message) {
    if (t == Termination::kCancelled && run_token.DeadlinePassed()) {
      // Stopped by the run's own deadline, not by the user.
      char limit[160];
      std::snprintf(limit,
                    sizeof limit,
                    "the run reached its time limit of %g s (solver.max_wall_s, drape run "
                    "--time-limit): ",
                    options.max_wall_s);
      t = Termination::kTimeLimit;
      message = limit + message.substr(message.find(' ') + 1);  // "cancelled in …" → "in …"
    }
    summary.termination = t;
    summary.message = std::move(message);
  }

  Scene scene;
  SolverOptions options;
  ShellModel model;
  std::vector<bool> released;            // per gripper
  std::unique_ptr<NodeContact> contact;  // null without obstacles
  double last_stabilization_force = 0;   // of the last converged step [N]
  // "auto" penalty: penetration held to options.penetration_tolerance by augmented-
  // Lagrangian passes. A penalty the user set is used as given.
  bool augment_contact = false;
  // The DOF map of the current stage, and the system built on it.
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<EquilibriumSystem> system;
  SystemTimers retired_timers;  // of systems replaced when a release changed the DOFs
  ShellState state;
  double weight_done = 0;  // weight factor reached by earlier stages
  double loads_done = 0;   // point-load factor reached by earlier stages
  const std::vector<StepObserver>* observers = nullptr;
  const CancellationToken* cancel = nullptr;
  // The token the run checks: the caller's, and the run's deadline.
  CancellationToken run_token;
  SolveSummary summary;
  Clock::time_point start;
  int last_negative_pivots = 0;
  // +1 while λ rises along the stage's path, −1 after a limit point turned it.
  int lambda_direction = 1;
  double stage_path_length = 0;  // Σ arc lengths accepted in the stage [m]
  // The mean element edge [m]: how far a nodal rotation moves its neighbours.
  double element_size = 0;
  // Finds where the fabric's own parts come close (layers of a fold).
  std::unique_ptr<SelfProximity> layers;
  // Keeps them apart (scene contact.self), null otherwise.
  std::unique_ptr<SelfContact> self_contact;
  // The reference surface's offsets from the flat plane (free DOFs at use):
  // decides the sign of a critical mode where both signs are stable.
  Eigen::VectorXd imperfection;
};

DofMap ShellSolver::Impl::StageDofs() const {
  DofMap d(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) d.FixNode(node, s.fixity);
  for (size_t g = 0; g < model.grippers.size(); ++g)
    if (!released[g])
      for (int node : model.grippers[g].nodes) d.FixNode(node, model.grippers[g].fixity);
  return d;
}

void ShellSolver::Impl::UseDofs(DofMap stage_dofs) {
  if (dofs && system && *dofs == stage_dofs) return;
  if (system) retired_timers += system->timers();
  system.reset();
  dofs = std::make_unique<DofMap>(std::move(stage_dofs));
  system = std::make_unique<EquilibriumSystem>(model, *dofs, contact.get());
  system->SetSelfContact(self_contact.get());
}

std::vector<HeldGripper> ShellSolver::Impl::Holds(const Stage& stage) const {
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

NewtonSettings ShellSolver::Impl::Newton() const {
  NewtonSettings n;
  n.tolerance = options.tolerance;
  n.max_iterations = options.max_iterations;
  n.divergence_ratio = options.divergence_ratio;
  n.stall_correction = options.displacement_tolerance * model.characteristic_length;
  return n;
}

ShellSolver::Impl::Augmentation ShellSolver::Impl::Augment(double lambda,
                                                           const StageLoading& loading,
                                                           ContinuationStep& step) {
  const double allowed = options.penetration_tolerance * model.thickness;
  Augmentation out;
  for (; out.passes < options.max_augmentations; ++out.passes) {
    if (contact->Report(state).max_penetration <= allowed) return out;
    const ShellState saved = state;
    const std::vector<double> multipliers = contact->multipliers();
    contact->Augment(state);
    const NewtonOutcome newton =
        SolveAtFixedLambda(lambda, loading, options.max_augmentation_iterations);
    if (newton.status != NewtonOutcome::Status::kConverged) {
      // Keep the last converged solution, and its forces: the reactions must
      // be those of the state kept, not of the failed pass's last iterate.
      state = saved;
      contact->SetMultipliers(multipliers);
      system->Assemble(state, /*with_tangent=*/false);
      out.shortfall = "augmented-Lagrangian pass " + std::to_string(out.passes + 1) +
                      " did not converge (" + newton.reason + ")";
      return out;
    }
    step.iterations += newton.iterations;
    step.residuals.insert(step.residuals.end(), newton.residuals.begin(), newton.residuals.end());
    step.convergence = newton.convergence;
    step.negative_pivots = newton.negative_pivots;
    ++summary.augmentations;
    summary.iterations += newton.iterations;
  }
  if (contact->Report(state).max_penetration > allowed)
    out.shortfall = "stopped after " + std::to_string(options.max_augmentations) +
                    " augmented-Lagrangian passes";
  return out;
}

bool ShellSolver::Impl::Emit(int stage_index,
                             int stage_step,
                             double lambda,
                             const StageLoading& loading,
                             const ContinuationStep& converged,
                             const StabilityEvent* classified) {
  ContinuationStep result = converged;
  Augmentation augmentation;
  if (contact && augment_contact) augmentation = Augment(lambda, loading, result);
  // The steppers refuse non-finite trial states; this keeps the promise that
  // no observer and no file ever sees one, whatever a future path does.
  if (!IsFinite(state)) {
    Stop(Termination::kNumericalFailure,
         "stage '" + scene.stages[stage_index].name + "': a converged state at λ = " +
             std::to_string(lambda) + " is not finite; it was not kept");
    return false;
  }
  StepState step;
  step.stage = stage_index;
  step.stage_name = scene.stages[stage_index].name;
  step.step = ++summary.steps;
  step.stage_step = stage_step;
  step.lambda = lambda;
  step.iterations = result.iterations;
  step.residuals = result.residuals;
  step.convergence = result.convergence;
  step.arc_length = result.arc_length;
  step.negative_pivots = result.negative_pivots;
  step.max_curvature = MaxPrincipalCurvature(model, state);
  step.law_curvature =
      model.section.bending_law ? MaxLawCurvature(model, state) : step.max_curvature;
  summary.max_curvature = std::max(summary.max_curvature, step.max_curvature);
  summary.max_law_curvature = std::max(summary.max_law_curvature, step.law_curvature);
  // What each support and gripper exerts on the fabric: F_int − F_ext at its
  // nodes (zero for a released gripper, whose nodes are free).
  const Eigen::VectorXd unbalanced = system->InternalForce() - loading.External(lambda, state);
  auto reaction = [&](const HeldNodes& held, bool active) {
    NamedVector r{held.name, Eigen::Vector3d::Zero()};
    if (active)
      for (int node : held.nodes) r.value += unbalanced.segment<3>(kDofsPerNode * node);
    step.reactions.push_back(r);
  };
  for (const auto& s : model.supports) reaction(s, true);
  for (size_t g = 0; g < model.grippers.size(); ++g) reaction(model.grippers[g], !released[g]);
  for (const auto& probe : model.probes)
    step.probes.push_back({probe.name, ProbePosition(model, probe, state)});
  if (contact) {
    step.contact = contact->Report(state);
    if (augment_contact) {
      step.contact->penetration_target = options.penetration_tolerance * model.thickness;
      step.contact->augmentation_passes = augmentation.passes;
      step.contact->augmentation_shortfall = augmentation.shortfall;
      if (!augmentation.shortfall.empty()) {
        ++summary.penetration_target_missed;
        if (step.contact->max_penetration > summary.worst_missed_penetration) {
          summary.worst_missed_penetration = step.contact->max_penetration;
          summary.worst_missed_step = step.step;
          summary.worst_missed_reason = augmentation.shortfall;
        }
      }
    }
    summary.max_penetration = std::max(summary.max_penetration, step.contact->max_penetration);
    summary.max_stabilization_force =
        std::max(summary.max_stabilization_force, step.contact->max_stabilization_force);
    last_stabilization_force = step.contact->max_stabilization_force;
    contact->Commit(state);
  }
  if (layers) {
    const double d = layers->SmallestDistance(state.positions, 2 * model.thickness);
    if (std::isfinite(d)) {
      step.layer_distance = d;
      // Infinite only where held nodes alone put layers inside the offset.
      if (const double f =
              self_contact ? self_contact->Evaluate(state.positions, false).force : NAN;
          std::isfinite(f))
        step.layer_force = f;
      if (d < summary.min_layer_distance) {
        summary.min_layer_distance = d;
        summary.min_layer_step = step.step;
      }
    }
  }
  step.state = state;
  step.elapsed_s = SecondsSince(start);

  // Against the unloaded start (0 negative pivots), so that a first step that
  // already lands past a buckling point is reported too. A switch onto a
  // stable branch keeps the count, and is an event all the same.
  if (result.negative_pivots != last_negative_pivots || classified) {
    StabilityEvent e;
    if (classified) {
      e = *classified;
    } else {
      e.kind = StabilityKind::kBifurcation;
      e.branch = Branch::kFundamental;
      e.lambda = lambda;
    }
    e.stage = stage_index;
    e.step = step.step;
    e.negative_pivots_before = last_negative_pivots;
    e.negative_pivots_after = result.negative_pivots;
    if (e.branch != Branch::kStable) e.negative_pivots_fundamental = result.negative_pivots;
    summary.stability_events.push_back(e);
    step.stability_event = e;
  }
  last_negative_pivots = result.negative_pivots;

  const auto observe_start = Clock::now();
  bool stop = false;
  for (const auto& observer : *observers)
    if (observer(step) == StepDecision::kStop) stop = true;
  summary.observer_s += SecondsSince(observe_start);
  if (stop)
    Stop(Termination::kStoppedByObserver,
         "an observer stopped the run after step " + std::to_string(step.step));
  return !stop;
}

bool ShellSolver::Impl::GrippersStayOutside(int index, const StageLoading& loading) {
  if (!contact || !loading.MovesGrippers()) return true;
  constexpr int kSamples = 64;
  ShellState placed = state;
  for (int k = 1; k <= kSamples; ++k) {
    const double lambda = static_cast<double>(k) / kSamples;
    loading.Place(lambda, placed);
    for (size_t g = 0; g < model.grippers.size(); ++g) {
      if (released[g]) continue;
      const auto inside = contact->Penetrations(placed, model.thickness, model.grippers[g].nodes);
      if (inside.empty()) continue;
      char where[120];
      std::snprintf(where, sizeof where, " at λ = %.3g", lambda);
      Stop(Termination::kIllPosed,
           "stage '" + scene.stages[index].name + "': gripper '" + model.grippers[g].name +
               "' is driven into an obstacle: " + inside.front() + where +
               "; change its path (stages[" + std::to_string(index) +
               "].moves) so that it stays outside");
      return false;
    }
  }
  return true;
}

std::string ShellSolver::Impl::ContactHint() const {
  if (!contact) return "";
  std::string hint;
  if (contact->stabilization() > 0 && contact->friction() == 0)
    // A hanging part slides off a frictionless form the way a chain runs off
    // a pulley: no stable rest exists for the path to reach.
    hint +=
        ". Nothing but frictionless contact holds the part (no support, no gripper): it can "
        "slide off the obstacle, so it may have no stable rest; give contact.friction, or "
        "hold it with a support";
  const double automatic = AutoPenalty(model);
  if (scene.contact && scene.contact->penalty && contact->penalty() > 3 * automatic) {
    char text[240];
    std::snprintf(text,
                  sizeof text,
                  ". contact.penalty %.3g N/m³ is %.0f times the automatic one (E h / ℓ² = %.3g): "
                  "so stiff a contact switches on and off abruptly; \"auto\" adapts it",
                  contact->penalty(),
                  contact->penalty() / automatic,
                  automatic);
    hint += text;
  }
  return hint;
}

std::string ShellSolver::Impl::WhatToChange(const Stage& spec, const StageSummary& stage) const {
  const std::string key = "stages[" + std::to_string(&spec - scene.stages.data()) + "]";
  if (stage.steps == 0)
    // Not even the smallest first step converged: the tangent at the start
    // barely resists the load (no bending, nothing holding the part) or the
    // load is far beyond it.
    return "not even a first step 2^" + std::to_string(options.max_step_cuts) +
           " times smaller than " + key +
           ".initial_increment converged: the part barely resists "
           "its load where it starts (material.bending, supports, grippers)" +
           ContactHint();
  return "the path turns or stiffens sharply here (contact, a snap, a fold): allow more "
         "cut-backs (solver.max_step_cuts), more iterations (solver.max_iterations), or the "
         "other solver.branching" +
         ContactHint();
}

bool ShellSolver::Impl::RetryAfterFailure(const ContinuationStep& step,
                                          const Stage& spec,
                                          double lambda,
                                          int& cuts_in_a_row,
                                          StageSummary& stage) {
  if (step.status == NewtonOutcome::Status::kCancelled) {
    Stop(Termination::kCancelled,
         "cancelled in stage '" + spec.name + "' at λ = " + std::to_string(lambda));
    return false;
  }
  if (cuts_in_a_row == options.max_step_cuts) {
    Stop(Termination::kStepTooSmall,
         "stage '" + spec.name + "' stopped at λ = " + std::to_string(lambda) + " after " +
             std::to_string(cuts_in_a_row) + " cut-backs: " + step.reason + "; " +
             WhatToChange(spec, stage));
    return false;
  }
  // Cut back and retry: counted only when it happens.
  ++cuts_in_a_row;
  ++stage.step_cuts;
  ++summary.step_cuts;
  return true;
}

NewtonOutcome ShellSolver::Impl::SolveAtFixedLambda(double lambda,
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

bool ShellSolver::Impl::Accept(const NewtonOutcome& newton,
                               StageSummary& stage,
                               const std::string& failure) {
  stage.iterations += newton.iterations;
  summary.iterations += newton.iterations;
  if (newton.status == NewtonOutcome::Status::kCancelled) {
    Stop(Termination::kCancelled, "cancelled in stage '" + stage.name + "'");
    return false;
  }
  if (newton.status != NewtonOutcome::Status::kConverged) {
    Stop(Termination::kStepTooSmall,
         "stage '" + stage.name + "' " + failure + ": " + newton.reason);
    return false;
  }
  return true;
}

namespace {

ContinuationStep StepOf(const NewtonOutcome& newton) {
  ContinuationStep step;
  step.iterations = newton.iterations;
  step.residuals = newton.residuals;
  step.convergence = newton.convergence;
  step.negative_pivots = newton.negative_pivots;
  return step;
}

}  // namespace

bool ShellSolver::Impl::RunHold(int index, const StageLoading& loading, StageSummary& stage) {
  const NewtonOutcome newton = SolveAtFixedLambda(1.0, loading);
  if (!Accept(newton, stage, "found no equilibrium")) return false;
  stage.steps = 1;
  stage.final_lambda = 1;
  return Emit(index, 1, 1.0, loading, StepOf(newton));
}

bool ShellSolver::Impl::Settle(int index, const StageLoading& loading, StageSummary& stage) {
  // Each pass shrinks the springs' force by about k_s / k of the structure;
  // stop at round-off of the weight.
  const double negligible = 1e-12 * model.total_weight.norm();
  for (int pass = 0; pass < kMaxSettlePasses; ++pass) {
    if (last_stabilization_force <= negligible) return true;
    const NewtonOutcome newton = SolveAtFixedLambda(1.0, loading);
    if (!Accept(newton, stage, "did not settle without its stabilisation")) return false;
    if (newton.iterations == 0) return true;  // already in equilibrium without them
    ++stage.steps;
    if (!Emit(index, stage.steps, 1.0, loading, StepOf(newton))) return false;
  }
  if (last_stabilization_force > negligible) {
    char note[200];
    std::snprintf(note,
                  sizeof note,
                  "stage '%s' ends with stabilisation springs still carrying up to %.3g N per "
                  "node (%.2g of the weight) after %d settle steps",
                  stage.name.c_str(),
                  last_stabilization_force,
                  last_stabilization_force / model.total_weight.norm(),
                  kMaxSettlePasses);
    summary.notes.push_back(note);
  }
  return true;
}

bool ShellSolver::Impl::RunLoadControl(int index,
                                       const StageLoading& loading,
                                       StageSummary& stage) {
  const Stage& spec = scene.stages[index];
  ArcLengthStepper stepper(*system, loading, Newton(), Psi());
  double lambda = 0;
  double increment = spec.initial_increment;
  int cuts_in_a_row = 0;
  while (lambda < 1.0) {
    if (summary.steps >= options.max_steps) {
      StopAtMaxSteps(spec, lambda);
      return false;
    }
    increment = std::min({increment, options.max_increment, 1.0 - lambda});
    // Land exactly on λ = 1 rather than leave a sliver of a step.
    if (1.0 - (lambda + increment) < 1e-12) increment = 1.0 - lambda;
    const ShellState saved = state;
    ContinuationStep step = stepper.StepTo(state, lambda, lambda + increment, cancel);
    stage.iterations += step.iterations;
    summary.iterations += step.iterations;
    if (step.status != NewtonOutcome::Status::kConverged) {
      state = saved;
      if (!RetryAfterFailure(step, spec, lambda, cuts_in_a_row, stage)) return false;
      increment /= 2;
      continue;
    }
    cuts_in_a_row = 0;
    std::optional<StabilityEvent> event;
    if (step.negative_pivots != last_negative_pivots) event = Classify(stepper, step);
    if (event && SwitchesAt(*event, step)) {
      // Located and switched with arc-length steps (the step's own length in
      // their metric); load control goes on from the branch.
      step.arc_length = stepper.Length(step.direction, lambda + increment, state);
      PathPoint branch;
      if (!PassBifurcation(index,
                           loading,
                           stepper,
                           PathPoint{saved, lambda, {}},
                           nullptr,
                           PathPoint{state, lambda + increment, step},
                           *event,
                           stage,
                           branch))
        return false;
      // Near the bifurcation λ grows with the square of the amplitude: a
      // step three times the switch's rise in λ doubles the amplitude, where
      // a full-size step's tangent predictor would shoot far along the
      // nearly free mode. Acceleration grows it back.
      increment = std::max(3 * (branch.lambda - summary.stability_events.back().lambda),
                           1e-4 * spec.initial_increment);
      lambda = branch.lambda;
      continue;
    }
    lambda += increment;
    ++stage.steps;
    stage.final_lambda = lambda;
    stage_path_length += stepper.Length(step.direction, lambda, state);
    step.arc_length = increment;
    if (!Emit(index, stage.steps, lambda, loading, step, event ? &*event : nullptr)) return false;
    if (options.acceleration) {
      const double gamma =
          static_cast<double>(options.target_iterations) / std::max(1, step.iterations);
      increment *= std::clamp(gamma, options.min_step_growth, options.max_step_growth);
    }
  }
  return true;
}

bool ShellSolver::Impl::RunArcLength(int index, const StageLoading& loading, StageSummary& stage) {
  const Stage& spec = scene.stages[index];
  ArcLengthStepper stepper(*system, loading, Newton(), Psi());
  double lambda = 0;
  double arc_length = 0;      // 0: size the first step from Δλ₀
  double max_arc_length = 0;  // set from the first step: max_increment in its units
  PathDirection previous;
  bool has_previous = false;
  int cuts_in_a_row = 0;
  double last_landing = NAN;  // λ where the last branch switch landed
  double lowest = 0;          // the smallest λ the path reached
  while (lambda < 1.0 - 1e-12) {
    if (summary.steps >= options.max_steps) {
      StopAtMaxSteps(spec, lambda);
      return false;
    }
    const ShellState saved = state;
    ContinuationStep step = stepper.Step(state,
                                         lambda,
                                         arc_length,
                                         spec.initial_increment,
                                         has_previous ? &previous : nullptr,
                                         1.0,
                                         cancel);
    stage.iterations += step.iterations;
    summary.iterations += step.iterations;
    if (max_arc_length == 0)
      max_arc_length = step.arc_length * options.max_increment / spec.initial_increment;
    if (step.status != NewtonOutcome::Status::kConverged) {
      state = saved;
      if (!RetryAfterFailure(step, spec, lambda, cuts_in_a_row, stage)) return false;
      arc_length = 0.5 * step.arc_length;
      continue;
    }
    // A snap-back may take λ below 0 for a while (a load that must reverse to
    // hold the shell on its path); a path that runs back past λ = −1 does
    // not come back to the stage's end.
    if (step.lambda < -1.0) {
      Stop(Termination::kStepTooSmall,
           "stage '" + spec.name +
               "': the path runs back past λ = −1 and does not reach the "
               "stage's end: past its limit points the part would snap, a jump no "
               "quasi-static path follows; change what the stage does (stages[" +
               std::to_string(index) + "]) or hold the part more (supports, grippers)");
      return false;
    }
    cuts_in_a_row = 0;
    std::optional<StabilityEvent> event;
    if (step.negative_pivots != last_negative_pivots) event = Classify(stepper, step);
    if (event && SwitchesAt(*event, step)) {
      PathPoint branch;
      if (!PassBifurcation(index,
                           loading,
                           stepper,
                           PathPoint{saved, lambda, {}},
                           has_previous ? &previous : nullptr,
                           PathPoint{state, event->lambda, step},
                           *event,
                           stage,
                           branch))
        return false;
      // Landing where the last switch landed: forward from there led back to
      // the same bifurcation (the branch bends back; the part would snap).
      // Let the path go the way the switch pointed instead of round again.
      if (std::abs(branch.lambda - last_landing) < 1e-6) stepper.SetDefiniteGoesForward(false);
      last_landing = branch.lambda;
      lambda = branch.lambda;
      previous = branch.step.direction;
      has_previous = true;
      // Grow from the switch's own length: the branch starts near the point.
      arc_length = std::min(branch.step.arc_length, max_arc_length);
      continue;
    }
    lambda = step.landed ? 1.0 : step.lambda;
    lowest = std::min(lowest, lambda);
    previous = step.direction;
    has_previous = true;
    ++stage.steps;
    stage.final_lambda = lambda;
    stage_path_length += step.arc_length;
    if (!Emit(index, stage.steps, lambda, loading, step, event ? &*event : nullptr)) return false;
    arc_length = step.arc_length;
    if (options.acceleration) {
      const double gamma =
          static_cast<double>(options.target_iterations) / std::max(1, step.iterations);
      arc_length *= std::clamp(gamma, options.min_step_growth, options.max_step_growth);
    }
    arc_length = std::min(arc_length, max_arc_length);
  }
  if (lowest < -1e-6) {
    // The end is an equilibrium, but the path to it needed the load
    // reversed: going forward, a real part jumps there instead.
    char note[320];
    std::snprintf(note,
                  sizeof note,
                  "stage '%s' reached λ = 1 only after its path ran back to λ = %.3g (the load "
                  "reversed): past a limit point the part would snap, and its end state is "
                  "reached by a jump no quasi-static path makes",
                  spec.name.c_str(),
                  lowest);
    summary.warnings.push_back(note);
  }
  return true;
}

bool ShellSolver::Impl::RunSequenced(int index, const StageLoading& loading, StageSummary& stage) {
  const auto begin = Clock::now();
  const Scene coarse_scene = CoarsenedScene(scene, options.sequencing);
  SolverOptions coarse_options = options;
  coarse_options.sequencing = 1;
  ShellSolver coarse(coarse_scene, coarse_options);
  const SolveSummary path = coarse.Solve({}, cancel);
  stage.iterations += path.iterations;
  summary.iterations += path.iterations;
  retired_timers += SystemTimers{path.assembly_s,
                                 path.factorization_s,
                                 path.solve_s,
                                 path.factorizations,
                                 path.indefinite_factorizations,
                                 path.reused_factorizations};
  if (path.termination == Termination::kCancelled) {
    Stop(Termination::kCancelled, "cancelled in stage '" + stage.name + "' (on the coarse mesh)");
    return false;
  }
  // What the coarse path met (a bifurcation switched, penetration short of
  // its target) is part of this run's story.
  for (const auto& w : path.warnings)
    if (std::find(model.warnings.begin(), model.warnings.end(), w) == model.warnings.end())
      summary.notes.push_back("on the coarse mesh: " + w);
  const auto [nx, ny] = *coarse_scene.fabric.mesh.elements;
  char where[160];
  std::snprintf(where,
                sizeof where,
                "mesh sequencing: the path on %d x %d elements (%d steps, %d iterations, %.3g s)",
                nx,
                ny,
                path.steps,
                path.iterations,
                path.total_s);
  auto fall_back = [&](const std::string& why) {
    summary.notes.push_back(std::string(where) + " " + why +
                            "; the path was followed on the scene's own mesh instead");
    state = model.reference;
    state.obstacles.assign(scene.obstacles.size(), ObstaclePlacement{});
    if (contact) contact->Commit(state);
    return RunPath(index, loading, stage);
  };
  if (path.termination != Termination::kCompleted) return fall_back("failed: " + path.message);
  state = Prolongate(coarse.model(), coarse.state(), model);
  const NewtonOutcome newton = SolveAtFixedLambda(1.0, loading);
  stage.iterations += newton.iterations;
  summary.iterations += newton.iterations;
  if (newton.status == NewtonOutcome::Status::kCancelled) {
    Stop(Termination::kCancelled, "cancelled in stage '" + stage.name + "'");
    return false;
  }
  if (newton.status != NewtonOutcome::Status::kConverged)
    return fall_back("ended where Newton on this mesh did not converge (" + newton.reason + ")");
  if (newton.negative_pivots > 0)
    return fall_back("ended where this mesh's tangent has " +
                     std::to_string(newton.negative_pivots) + " negative pivots");
  char done[120];
  std::snprintf(done,
                sizeof done,
                ", then %d Newton iterations on this mesh from its end (%.3g s in all)",
                newton.iterations,
                SecondsSince(begin));
  summary.notes.push_back(std::string(where) + done);
  stage.steps = 1;
  stage.final_lambda = 1;
  return Emit(index, 1, 1.0, loading, StepOf(newton));
}

StabilityEvent ShellSolver::Impl::Classify(ArcLengthStepper& stepper,
                                           const ContinuationStep& step) {
  StabilityEvent e;
  const int direction = stepper.LambdaDirection(state, step.lambda, step.direction);
  e.kind = direction != lambda_direction ? StabilityKind::kLimit : StabilityKind::kBifurcation;
  e.branch = e.kind == StabilityKind::kLimit ? Branch::kNone : Branch::kFundamental;
  e.lambda = step.lambda;
  lambda_direction = direction;
  return e;
}

bool ShellSolver::Impl::PassBifurcation(int index,
                                        const StageLoading& loading,
                                        ArcLengthStepper& stepper,
                                        const PathPoint& start,
                                        const PathDirection* previous,
                                        const PathPoint& crossing,
                                        StabilityEvent event,
                                        StageSummary& stage,
                                        PathPoint& reached) {
  const std::string& name = scene.stages[index].name;
  BifurcationSettings settings;
  settings.locate_fraction = kLocateFraction;
  settings.path_before = stage_path_length;
  settings.amplitude = kSwitchAmplitude * model.characteristic_length;
  settings.rotation_length = element_size;
  if (imperfection.size() == model.DofCount()) settings.imperfection = dofs->Restrict(imperfection);
  const int before = last_negative_pivots;
  const BranchSwitch sw =
      SwitchBranch(stepper, *system, start, previous, crossing, before, settings, cancel);
  stage.iterations += sw.iterations;
  summary.iterations += sw.iterations;
  if (sw.cancelled) {
    state = start.state;
    Stop(Termination::kCancelled, "cancelled in stage '" + name + "' at a bifurcation");
    return false;
  }
  if (!sw.switched) {
    // Keep the last stable point the bisection found: the part's state just
    // before it would snap.
    state = start.state;
    if (sw.bifurcation) {
      state = sw.bifurcation->state;
      ++stage.steps;
      stage.final_lambda = sw.bifurcation->lambda;
      if (!Emit(index, stage.steps, sw.bifurcation->lambda, loading, sw.bifurcation->step))
        return false;
    }
    char where[160];
    std::snprintf(where,
                  sizeof where,
                  "stage '%s': the path bifurcates at λ = %.6g (negative pivots %d -> %d) and "
                  "no branch past it could be followed: ",
                  name.c_str(),
                  sw.lambda,
                  before,
                  sw.negative_pivots_fundamental);
    Stop(Termination::kNoStableBranch,
         where + sw.failure +
             ". The primary path past it is unstable; solver.branching: fundamental follows "
             "it anyway" +
             ContactHint());
    return false;
  }
  if (sw.bifurcation) {
    state = sw.bifurcation->state;
    ++stage.steps;
    stage.final_lambda = sw.bifurcation->lambda;
    stage_path_length += sw.bifurcation->step.arc_length;
    if (!Emit(index, stage.steps, sw.bifurcation->lambda, loading, sw.bifurcation->step))
      return false;
  }
  state = sw.branch.state;
  event.lambda = sw.lambda;
  event.branch = sw.kind;
  event.negative_pivots_fundamental = sw.negative_pivots_fundamental;
  event.modes = sw.modes;
  event.mode_max_displacement = sw.max_displacement;
  event.switch_iterations = sw.iterations;
  event.switch_s = sw.seconds;
  ++summary.branch_switches;
  ++stage.steps;
  stage.final_lambda = sw.branch.lambda;
  stage_path_length += sw.branch.step.arc_length;
  reached = sw.branch;
  return Emit(index, stage.steps, sw.branch.lambda, loading, sw.branch.step, &event);
}

bool ShellSolver::Impl::RunStage(int index) {
  const Stage& spec = scene.stages[index];
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
      stage.time_s = SecondsSince(start);
      summary.stages.push_back(stage);
    }
  } finish{summary, stage, stage_start};

  for (const auto& name : spec.release)
    for (size_t g = 0; g < model.grippers.size(); ++g)
      if (model.grippers[g].name == name) released[g] = true;
  DofMap stage_dofs = StageDofs();
  if (contact) {
    // Springs (see node_contact.h) only where contact alone must hold the
    // fabric; 1e-8 of the membrane stiffness per node keeps such a pivot
    // well above the zero-pivot bound while its force stays small.
    const bool needed = !HoldsRestrainRigidMotion(model, stage_dofs);
    std::vector<bool> held(model.NodeCount());
    for (int i = 0; i < model.NodeCount(); ++i) held[i] = stage_dofs.IsFixed(kDofsPerNode * i);
    contact->SetStabilization(
        needed ? kStabilization * model.section.membrane.diagonal().maxCoeff() : 0.0,
        std::move(held));
  }
  if (!contact && stage_dofs.FreeCount() == stage_dofs.DofCount()) {
    Stop(Termination::kIllPosed,
         "stage '" + spec.name + "': nothing holds the fabric (every support and gripper is " +
             "released), so it would move as a rigid body; keep a support or a gripper");
    return false;
  }
  UseDofs(std::move(stage_dofs));
  std::vector<MovedObstacle> moved;
  for (const auto& move : spec.moves)
    for (size_t o = 0; o < scene.obstacles.size(); ++o)
      if (!move.obstacle.empty() && scene.obstacles[o].name == move.obstacle)
        moved.push_back({static_cast<int>(o), &move.path, state.obstacles.at(o)});
  const StageLoading loading(model, spec, Holds(spec), weight_done, loads_done, std::move(moved));
  if (!GrippersStayOutside(index, loading)) return false;
  lambda_direction = 1;
  stage_path_length = 0;

  bool ok;
  if (spec.kind == StageKind::kHold)
    ok = RunHold(index, loading, stage);
  else if (options.sequencing > 1)
    ok = RunSequenced(index, loading, stage);
  else
    ok = RunPath(index, loading, stage);
  if (ok && contact && contact->stabilization() > 0) ok = Settle(index, loading, stage);
  if (ok) summary.final_negative_pivots = last_negative_pivots;
  if (ok && last_negative_pivots > 0) {
    // Only with `fundamental` branching, past a limit point, or on a branch
    // that is itself unstable: say so rather than let it pass as converged.
    char note[320];
    std::snprintf(
        note,
        sizeof note,
        "stage '%s' ends at step %d on an unstable equilibrium: its tangent has %d "
        "negative pivot%s (a real part would not rest there)%s",
        spec.name.c_str(),
        summary.steps,
        last_negative_pivots,
        last_negative_pivots == 1 ? "" : "s",
        options.branching == Branching::kFundamental ? "; solver.branching is fundamental" : "");
    summary.warnings.push_back(note);
  }
  if (ok) {
    weight_done = loading.WeightFactor(1.0);
    loads_done = loading.LoadFactor(1.0);
  }
  return ok;
}

ShellSolver::ShellSolver(const Scene& scene, const SolverOptions& options)
    : ShellSolver(scene, BuildShellModel(scene), options) {}

// The solver keeps the scene on the mesh it solves (a preset's density
// applied), so that sequencing coarsens that mesh.
ShellSolver::ShellSolver(const Scene& scene, ShellModel model, const SolverOptions& options)
    : impl_(std::make_unique<Impl>(SceneOnSolvedMesh(scene), std::move(model), options)) {
  if (impl_->model.supports.empty() && impl_->model.grippers.empty() && !impl_->contact)
    throw SceneError("supports",
                     "nothing holds the fabric: it is free to move as a rigid body; add a support "
                     "or a gripper");
  CheckHoldsDoNotConflict(scene, impl_->model);
  CheckSequencing(impl_->scene, options.sequencing);
}

ShellSolver::~ShellSolver() = default;

const ShellModel& ShellSolver::model() const {
  return impl_->model;
}
const ShellState& ShellSolver::state() const {
  return impl_->state;
}

DragBasis ShellSolver::BasisForDrag(const std::string& gripper) {
  Impl& m = *impl_;
  DragBasis basis;
  for (size_t g = 0; g < m.model.grippers.size(); ++g)
    if (m.model.grippers[g].name == gripper) basis.gripper = static_cast<int>(g);
  if (basis.gripper < 0) {
    std::string names;
    for (const auto& g : m.model.grippers) names += (names.empty() ? "'" : ", '") + g.name + "'";
    throw std::invalid_argument(
        "the scene has no gripper '" + gripper + "'" +
        (names.empty() ? std::string(" (it has none)") : " (it has " + names + ")"));
  }
  if (m.summary.termination != Termination::kCompleted || !m.system)
    throw std::invalid_argument("the run did not complete every stage (" + m.summary.message +
                                "): there is no end state to drag from");
  if (m.released[basis.gripper])
    throw std::invalid_argument("gripper '" + gripper +
                                "' is released by the scene's stages: only a held gripper can "
                                "be dragged");
  basis.model = &m.model;
  basis.system = m.system.get();
  basis.contact = m.contact.get();
  basis.state = m.state;
  basis.weight_factor = m.weight_done;
  basis.load_factor = m.loads_done;
  return basis;
}

SolveSummary ShellSolver::Solve(const std::vector<StepObserver>& observers,
                                const CancellationToken* cancel) {
  Impl& m = *impl_;
  m.summary = SolveSummary();
  m.start = Clock::now();
  m.observers = &observers;
  m.run_token.Follow(cancel);
  if (m.options.max_wall_s > 0)
    m.run_token.SetDeadline(m.start + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(m.options.max_wall_s)));
  m.cancel = &m.run_token;
  m.summary.nodes = m.model.NodeCount();
  m.summary.elements = m.model.mesh.ElementCount();
  m.summary.dofs = m.model.DofCount();
  m.summary.warnings = m.model.warnings;
  m.summary.bending_valid_to = m.model.bending_valid_to;
  std::string error;
  if (!m.options.IsValid(&error)) {
    m.Stop(Termination::kInvalidInput, error);
    return m.summary;
  }
#ifdef _OPENMP
  if (m.options.threads > 0) omp_set_num_threads(m.options.threads);
  m.summary.threads_used = omp_get_max_threads();
#else
  m.summary.threads_used = 1;
#endif
  m.state = m.model.reference;
  m.state.obstacles.assign(m.scene.obstacles.size(), ObstaclePlacement{});
  if (m.contact) {
    m.contact->Commit(m.state);
    m.summary.contact_penalty = m.contact->penalty();
  }
  m.weight_done = m.loads_done = 0;
  m.released.assign(m.model.grippers.size(), false);
  m.last_negative_pivots = 0;
  m.element_size = MeanEdgeLength(m.model.mesh);
  // Parts count as distinct layers when farther apart at rest than a few
  // elements (a fold's hinge bends them close) and than ten thicknesses.
  m.summary.layer_exclusion = std::max(4 * m.element_size, 10 * m.model.thickness);
  m.layers = std::make_unique<SelfProximity>(m.model.mesh, m.summary.layer_exclusion);
  m.self_contact.reset();
  if (!m.scene.contact || m.scene.contact->self) {
    SelfContactSettings s;
    s.offset = m.scene.contact && m.scene.contact->thickness ? *m.scene.contact->thickness
                                                             : m.model.thickness;
    s.activation = 0.5 * s.offset;
    s.exclusion = m.summary.layer_exclusion;
    // Stiffness: the barrier halfway into its band carries ten times a
    // node's weight (its force there is κ·1.19ŝ·2(ξ + d̂/2), b'(ŝ/2) = −1.19ŝ);
    // closer, the log barrier grows without bound.
    const double s_hat = 2 * s.offset * s.activation + s.activation * s.activation;
    const double node_weight = m.model.total_weight.norm() / std::max(1, m.model.NodeCount());
    s.stiffness =
        10 * std::max(node_weight, 1e-12) / (2.39 * s_hat * (s.offset + 0.5 * s.activation));
    m.self_contact = std::make_unique<SelfContact>(m.model.mesh, s);
  }
  m.imperfection = Eigen::VectorXd::Zero(m.model.DofCount());
  for (int i = 0; i < m.model.NodeCount(); ++i)
    m.imperfection(kDofsPerNode * i + 2) = m.model.mesh.positions(i, 2) - m.scene.fabric.elevation;
  if (m.imperfection.cwiseAbs().maxCoeff() == 0) m.imperfection.resize(0);
  m.retired_timers = SystemTimers();
  m.system.reset();
  m.dofs.reset();

  bool completed = true;
  try {
    for (int i = 0; i < static_cast<int>(m.scene.stages.size()) && completed; ++i)
      completed = m.RunStage(i);
    if (completed) m.Stop(Termination::kCompleted, "every stage reached λ = 1");
  } catch (const std::exception& e) {
    // CHOLMOD out of memory and the like: the steps reached so far stay valid.
    m.Stop(Termination::kNumericalFailure, e.what());
  }

  if (m.summary.min_layer_distance <
      (m.self_contact ? m.self_contact->settings().offset : m.model.thickness)) {
    char warning[400];
    std::snprintf(warning,
                  sizeof warning,
                  "the fabric passes into itself: at step %d two of its parts (more than %.3g m "
                  "apart at rest) are %.3g m apart, %.2f of its thickness%s",
                  m.summary.min_layer_step,
                  m.summary.layer_exclusion,
                  m.summary.min_layer_distance,
                  m.summary.min_layer_distance / m.model.thickness,
                  m.self_contact ? " (closer than contact.thickness: held there by a gripper?)"
                                 : "; contact.self keeps layers apart");
    m.summary.warnings.push_back(warning);
  }
  if (m.summary.penetration_target_missed > 0) {
    char warning[400];
    std::snprintf(warning,
                  sizeof warning,
                  "contact: the penetration target (%.3g %% of the thickness, %.3g m) was not "
                  "reached in %d step%s; the deepest, %.3g m (%.2g %% of the thickness) at step "
                  "%d: %s",
                  100 * m.options.penetration_tolerance,
                  m.options.penetration_tolerance * m.model.thickness,
                  m.summary.penetration_target_missed,
                  m.summary.penetration_target_missed == 1 ? "" : "s",
                  m.summary.worst_missed_penetration,
                  100 * m.summary.worst_missed_penetration / m.model.thickness,
                  m.summary.worst_missed_step,
                  m.summary.worst_missed_reason.c_str());
    m.summary.warnings.push_back(warning);
  }
  SystemTimers t = m.retired_timers;
  if (m.system) t += m.system->timers();
  m.summary.free_dofs = m.dofs ? m.dofs->FreeCount() : -1;
  m.summary.assembly_s = t.assembly_s;
  m.summary.factorization_s = t.factorization_s;
  m.summary.solve_s = t.solve_s;
  m.summary.factorizations = t.factorizations;
  m.summary.indefinite_factorizations = t.indefinite_factorizations;
  m.summary.reused_factorizations = t.reused_factorizations;
  m.summary.total_s = SecondsSince(m.start);
  m.summary.peak_memory_bytes = PeakMemoryBytes();
  return m.summary;
}

}  // namespace drape
