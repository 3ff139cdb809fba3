#include "core/solve/shell_solver.h"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <utility>

#include "core/contact/contact_setup.h"
#include "core/linalg/machine_resources.h"
#include "core/model/fabric_mesh.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/solve/gripper_drag.h"
#include "core/solve/mesh_sequencing.h"
#include "core/solve/run_diagnostics.h"
#include "core/solve/solve_run.h"
#include "core/solve/stage_runner.h"
#include "core/solve/well_posedness.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

// The run's parts at the start: the reference state, no stage done, the
// layers' proximity and self-contact, the imperfection that picks a mode's
// sign, and no system yet (the first stage builds it).
void PrepareRun(SolveRun& run) {
  const ShellModel& model = run.model;
  run.state = model.reference;
  run.state.obstacles.assign(run.scene.obstacles.size(), ObstaclePlacement{});
  if (run.contact) {
    run.contact->Commit(run.state);
    run.summary.contact_penalty = run.contact->penalty();
  }
  run.weight_done = run.loads_done = 0;
  run.released.assign(model.grippers.size(), false);
  run.element_size = MeanEdgeLength(model.mesh);
  run.summary.layer_exclusion = LayerExclusion(model, run.element_size);
  run.layers = std::make_unique<SelfProximity>(model.mesh, run.summary.layer_exclusion);
  run.self_contact.reset();
  if (!run.scene.contact || run.scene.contact->self)
    run.self_contact = std::make_unique<SelfContact>(
        model.mesh, SelfContactSettingsFor(run.scene, model, run.summary.layer_exclusion));
  run.imperfection = Eigen::VectorXd::Zero(model.DofCount());
  const Eigen::VectorXd flat = PartElevations(run.scene, model.mesh);
  for (int i = 0; i < model.NodeCount(); ++i)
    run.imperfection(kDofsPerNode * i + 2) = model.mesh.positions(i, 2) - flat(i);
  if (run.imperfection.cwiseAbs().maxCoeff() == 0) run.imperfection.resize(0);
  run.retired_timers = SystemTimers();
  run.system.reset();
  run.dofs.reset();
}

// Every stage in order, until one stops the run.
StageOutcome RunStages(SolveRun& run) {
  try {
    for (int i = 0; i < static_cast<int>(run.scene.stages.size()); ++i)
      if (StageOutcome o = RunStage(run, i); !o.GoesOn()) return o;
    return StageOutcome::Stop(Termination::kCompleted, "every stage reached λ = 1");
  } catch (const std::exception& e) {
    // CHOLMOD out of memory and the like: the steps reached so far stay valid.
    return StageOutcome::Stop(Termination::kNumericalFailure, e.what());
  }
}

// Where the time and the factorisations went, over every system of the run.
void SummarizeCosts(SolveRun& run) {
  SystemTimers t = run.retired_timers;
  if (run.system) t += run.system->timers();
  SolveSummary& s = run.summary;
  s.free_dofs = run.dofs ? run.dofs->FreeCount() : -1;
  s.assembly_s = t.assembly_s;
  s.factorization_s = t.factorization_s;
  s.solve_s = t.solve_s;
  s.factorizations = t.factorizations;
  s.indefinite_factorizations = t.indefinite_factorizations;
  s.reused_factorizations = t.reused_factorizations;
  s.total_s = std::chrono::duration<double>(Clock::now() - run.start).count();
  s.peak_memory_bytes = PeakMemoryBytes();
}

// `options` with `sequencing: auto` resolved for the scene on its solved mesh.
SolverOptions WithSequencingChosen(const Scene& solved, SolverOptions options) {
  options.sequencing_auto = options.sequencing == kAutoSequencing;
  options.sequencing = ChosenSequencing(solved, options.sequencing);
  return options;
}

}  // namespace

struct ShellSolver::Impl {
  Impl(const Scene& scene, ShellModel model, const SolverOptions& options)
      : run(scene, std::move(model), WithSequencingChosen(scene, options)) {}
  SolveRun run;
};

ShellSolver::ShellSolver(const Scene& scene, const SolverOptions& options)
    : ShellSolver(scene, BuildShellModel(scene), options) {}

// The solver keeps the scene on the mesh it solves (a preset's density
// applied), so that sequencing coarsens that mesh.
ShellSolver::ShellSolver(const Scene& scene, ShellModel model, const SolverOptions& options)
    : impl_(std::make_unique<Impl>(SceneOnSolvedMesh(scene), std::move(model), options)) {
  const SolveRun& run = impl_->run;
  if (run.model.supports.empty() && run.model.grippers.empty() && !run.contact)
    throw SceneError("supports",
                     "nothing holds the fabric: it is free to move as a rigid body; add a support "
                     "or a gripper");
  CheckHoldsDoNotConflict(scene, run.model);
  CheckSequencing(run.scene, run.options.sequencing);
}

ShellSolver::~ShellSolver() = default;

const ShellModel& ShellSolver::model() const {
  return impl_->run.model;
}
const ShellState& ShellSolver::state() const {
  return impl_->run.state;
}

DragBasis ShellSolver::BasisForDrag(const std::string& gripper) {
  SolveRun& run = impl_->run;
  DragBasis basis;
  for (size_t g = 0; g < run.model.grippers.size(); ++g)
    if (run.model.grippers[g].name == gripper) basis.gripper = static_cast<int>(g);
  if (basis.gripper < 0) {
    std::string names;
    for (const auto& g : run.model.grippers) names += (names.empty() ? "'" : ", '") + g.name + "'";
    throw std::invalid_argument(
        "the scene has no gripper '" + gripper + "'" +
        (names.empty() ? std::string(" (it has none)") : " (it has " + names + ")"));
  }
  if (run.summary.termination != Termination::kCompleted || !run.system)
    throw std::invalid_argument("the run did not complete every stage (" + run.summary.message +
                                "): there is no end state to drag from");
  if (run.released[basis.gripper])
    throw std::invalid_argument("gripper '" + gripper +
                                "' is released by the scene's stages: only a held gripper can "
                                "be dragged");
  basis.model = &run.model;
  basis.system = run.system.get();
  basis.contact = run.contact.get();
  basis.state = run.state;
  basis.weight_factor = run.weight_done;
  basis.load_factor = run.loads_done;
  return basis;
}

SolveSummary ShellSolver::Solve(const std::vector<StepObserver>& observers,
                                const CancellationToken* cancel) {
  SolveRun& run = impl_->run;
  run.summary = SolveSummary();
  run.start = Clock::now();
  run.recorder = std::make_unique<StepRecorder>(run.summary, observers, run.start);
  run.run_token.Follow(cancel);
  if (run.options.max_wall_s > 0)
    run.run_token.SetDeadline(run.start +
                              std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(run.options.max_wall_s)));
  run.cancel = &run.run_token;
  run.summary.nodes = run.model.NodeCount();
  run.summary.elements = run.model.mesh.ElementCount();
  run.summary.dofs = run.model.DofCount();
  run.summary.warnings = run.model.warnings;
  run.summary.bending_valid_to = run.model.bending_valid_to;
  if (std::string error; !run.options.IsValid(&error)) {
    Conclude(run, StageOutcome::Stop(Termination::kInvalidInput, error));
    return run.summary;
  }
  run.summary.threads_used = UseAssemblyThreads(run.options.threads);
  PrepareRun(run);
  Conclude(run, RunStages(run));
  AddEndOfRunWarnings(run);
  SummarizeCosts(run);
  return run.summary;
}

}  // namespace drape
