#include "core/solve/shell_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/model/scene_error.h"
#include "core/solve/dof_map.h"
#include "core/solve/equilibrium_system.h"
#include "core/solve/newton_solver.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

DofMap MakeDofMap(const ShellModel& model) {
  DofMap dofs(model.NodeCount());
  // Grippers hold their nodes where they are until move stages exist.
  for (const auto* group : {&model.supports, &model.grippers})
    for (const auto& held : *group)
      for (int node : held.nodes) dofs.FixNode(node, held.fixity);
  return dofs;
}

}  // namespace

struct ShellSolver::Impl {
  Impl(const Scene& s, ShellModel m, const SolverOptions& o)
      : scene(s), options(o), model(std::move(m)), dofs(MakeDofMap(model)) {}

  Eigen::VectorXd External(const ShellState& state) const;
  Eigen::VectorXd PointLoads(const ShellState& state) const;
  // ‖F_ref‖ of a stage over the free DOFs: what λ multiplies.
  double StageLoadNorm(StageKind kind, const ShellState& state) const;
  NewtonSettings Newton() const;
  // Runs one stage; returns false when the run must stop (summary says why).
  bool RunStage(int index);
  bool RunHoldStage(int index, StageSummary& stage);
  bool Emit(int stage_index,
            int stage_step,
            double lambda,
            const NewtonOutcome& newton,
            double arc_length);
  void Stop(Termination t, std::string message) {
    summary.termination = t;
    summary.message = std::move(message);
  }

  Scene scene;
  SolverOptions options;
  ShellModel model;
  DofMap dofs;
  std::optional<EquilibriumSystem> system;
  ShellState state;
  double weight_factor = 0;  // λ of the self-weight
  double load_factor = 0;    // λ of the point loads
  double reference_force = 0;
  const std::vector<StepObserver>* observers = nullptr;
  const CancellationToken* cancel = nullptr;
  SolveSummary summary;
  Clock::time_point start;
  int last_negative_pivots = 0;
};

Eigen::VectorXd ShellSolver::Impl::PointLoads(const ShellState& s) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
  for (const auto& load : model.loads)
    for (int node : load.nodes) {
      f.segment<3>(kDofsPerNode * node) += load.force_per_node;
      // A moment M does work M·w on the rotation w = a g₁ + b g₂.
      const Eigen::Matrix3d& r = s.rotations[node];
      f(kDofsPerNode * node + 3) += load.moment_per_node.dot(r.col(0));
      f(kDofsPerNode * node + 4) += load.moment_per_node.dot(r.col(1));
    }
  return f;
}

Eigen::VectorXd ShellSolver::Impl::External(const ShellState& s) const {
  Eigen::VectorXd f = weight_factor * model.weight_load;
  if (load_factor != 0) f += load_factor * PointLoads(s);
  return f;
}

double ShellSolver::Impl::StageLoadNorm(StageKind kind, const ShellState& s) const {
  return dofs.Restrict(kind == StageKind::kGravity ? model.weight_load : PointLoads(s)).norm();
}

NewtonSettings ShellSolver::Impl::Newton() const {
  NewtonSettings n;
  n.tolerance = options.tolerance;
  n.max_iterations = options.max_iterations;
  n.divergence_ratio = options.divergence_ratio;
  // Below ~1e-11 of the loads the residual is round-off in the membrane forces.
  n.residual_floor = 1e-11 * reference_force;
  n.displacement_floor = options.displacement_tolerance * model.characteristic_length;
  return n;
}

bool ShellSolver::Impl::Emit(int stage_index,
                             int stage_step,
                             double lambda,
                             const NewtonOutcome& newton,
                             double arc_length) {
  StepState step;
  step.stage = stage_index;
  step.stage_name = scene.stages[stage_index].name;
  step.step = ++summary.steps;
  step.stage_step = stage_step;
  step.lambda = lambda;
  step.iterations = newton.iterations;
  step.residuals = newton.residuals;
  step.arc_length = arc_length;
  step.negative_pivots = newton.negative_pivots;
  // What each support and gripper exerts on the fabric: F_int − F_ext at its nodes.
  const Eigen::VectorXd unbalanced = system->InternalForce() - External(state);
  for (const auto* group : {&model.supports, &model.grippers})
    for (const auto& held : *group) {
      NamedVector r{held.name, Eigen::Vector3d::Zero()};
      for (int node : held.nodes) r.value += unbalanced.segment<3>(kDofsPerNode * node);
      step.reactions.push_back(r);
    }
  for (const auto& probe : model.probes)
    step.probes.push_back({probe.name, ProbePosition(model, probe, state)});
  step.state = state;
  step.elapsed_s = SecondsSince(start);

  if (step.step > 1 && newton.negative_pivots != last_negative_pivots)
    summary.stability_events.push_back(
        {stage_index, step.step, lambda, last_negative_pivots, newton.negative_pivots});
  last_negative_pivots = newton.negative_pivots;

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

bool ShellSolver::Impl::RunHoldStage(int index, StageSummary& stage) {
  NewtonOutcome newton = SolveEquilibrium(
      *system, [&](const ShellState& s) { return External(s); }, Newton(), state, cancel);
  stage.iterations += newton.iterations;
  summary.iterations += newton.iterations;
  if (newton.status == NewtonOutcome::Status::kCancelled) {
    Stop(Termination::kCancelled, "cancelled in stage '" + stage.name + "'");
    return false;
  }
  if (newton.status != NewtonOutcome::Status::kConverged) {
    Stop(Termination::kStepTooSmall,
         "stage '" + stage.name + "' found no equilibrium: " + newton.reason);
    return false;
  }
  stage.steps = 1;
  stage.final_lambda = 1;
  return Emit(index, 1, 1.0, newton, 0.0);
}

bool ShellSolver::Impl::RunStage(int index) {
  const Stage& spec = scene.stages[index];
  StageSummary stage;
  stage.name = spec.name;
  stage.kind = spec.kind;
  stage.control_given = spec.control;
  stage.control_used = StepControl::kLoad;
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

  if (spec.kind == StageKind::kHold) return RunHoldStage(index, stage);
  if (spec.control == StepControl::kArcLength)
    summary.notes.push_back("stage '" + spec.name +
                            "': arc-length control is not available yet; load control was used");
  double& factor = spec.kind == StageKind::kGravity ? weight_factor : load_factor;
  factor = 0;
  double lambda = 0;
  double increment = spec.initial_increment;
  int cuts_in_a_row = 0;
  // The last converged step, for the secant predictor.
  ShellState previous = state;
  double previous_increment = 0;

  while (lambda < 1.0) {
    if (summary.steps >= options.max_steps) {
      Stop(Termination::kMaxStepsReached,
           "stage '" + spec.name + "' needed more than " + std::to_string(options.max_steps) +
               " steps");
      return false;
    }
    increment = std::min({increment, options.max_increment, 1.0 - lambda});
    // Land exactly on λ = 1 rather than leave a sliver of a step.
    if (1.0 - (lambda + increment) < 1e-12) increment = 1.0 - lambda;
    const ShellState saved = state;
    factor = lambda + increment;
    if (previous_increment > 0)
      state = Extrapolate(previous, saved, increment / previous_increment);
    NewtonSettings newton_settings = Newton();
    newton_settings.residual_reference = increment * StageLoadNorm(spec.kind, saved);
    NewtonOutcome newton = SolveEquilibrium(
        *system, [&](const ShellState& s) { return External(s); }, newton_settings, state, cancel);
    stage.iterations += newton.iterations;
    summary.iterations += newton.iterations;
    if (newton.status == NewtonOutcome::Status::kCancelled) {
      state = saved;
      factor = lambda;
      Stop(Termination::kCancelled,
           "cancelled in stage '" + spec.name + "' at λ = " + std::to_string(lambda));
      return false;
    }
    if (newton.status != NewtonOutcome::Status::kConverged) {
      state = saved;
      factor = lambda;
      ++stage.step_cuts;
      ++summary.step_cuts;
      if (++cuts_in_a_row > options.max_step_cuts) {
        Stop(Termination::kStepTooSmall,
             "stage '" + spec.name + "' stopped at λ = " + std::to_string(lambda) + " after " +
                 std::to_string(options.max_step_cuts) + " cut-backs: " + newton.reason);
        return false;
      }
      increment /= 2;
      continue;
    }
    cuts_in_a_row = 0;
    previous = saved;
    previous_increment = increment;
    lambda += increment;
    ++stage.steps;
    stage.final_lambda = lambda;
    if (!Emit(index, stage.steps, lambda, newton, increment)) return false;
    if (options.acceleration) {
      const double gamma =
          static_cast<double>(options.target_iterations) / std::max(1, newton.iterations);
      increment *= std::clamp(gamma, options.min_step_growth, options.max_step_growth);
    }
  }
  factor = 1.0;
  return true;
}

ShellSolver::ShellSolver(const Scene& scene, const SolverOptions& options)
    : ShellSolver(scene, BuildShellModel(scene), options) {}

ShellSolver::ShellSolver(const Scene& scene, ShellModel model, const SolverOptions& options)
    : impl_(std::make_unique<Impl>(scene, std::move(model), options)) {
  if (impl_->dofs.FreeCount() == impl_->dofs.DofCount())
    throw SceneError("supports",
                     "nothing holds the fabric: it is free to move as a rigid body; add a support "
                     "or a gripper");
}

ShellSolver::~ShellSolver() = default;

const ShellModel& ShellSolver::model() const {
  return impl_->model;
}
const ShellState& ShellSolver::state() const {
  return impl_->state;
}

SolveSummary ShellSolver::Solve(const std::vector<StepObserver>& observers,
                                const CancellationToken* cancel) {
  Impl& m = *impl_;
  m.summary = SolveSummary();
  m.start = Clock::now();
  m.observers = &observers;
  m.cancel = cancel;
  m.summary.nodes = m.model.NodeCount();
  m.summary.elements = m.model.mesh.ElementCount();
  m.summary.dofs = m.model.DofCount();
  m.summary.free_dofs = m.dofs.FreeCount();
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
  m.weight_factor = m.load_factor = 0;
  m.last_negative_pivots = 0;
  m.reference_force = m.model.weight_load.norm();
  for (const auto& load : m.model.loads)
    m.reference_force +=
        std::sqrt(static_cast<double>(load.nodes.size())) *
        (load.force_per_node.norm() + load.moment_per_node.norm() / m.model.characteristic_length);
  m.system.emplace(m.model, m.dofs);

  bool completed = true;
  for (int i = 0; i < static_cast<int>(m.scene.stages.size()) && completed; ++i)
    completed = m.RunStage(i);
  if (completed) m.Stop(Termination::kCompleted, "every stage reached λ = 1");

  const SystemTimers& t = m.system->timers();
  m.summary.assembly_s = t.assembly_s;
  m.summary.factorization_s = t.factorization_s;
  m.summary.solve_s = t.solve_s;
  m.summary.factorizations = t.factorizations;
  m.summary.ldlt_factorizations = t.ldlt_factorizations;
  m.summary.total_s = SecondsSince(m.start);
  return m.summary;
}

}  // namespace drape
