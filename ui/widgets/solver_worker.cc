#include "ui/widgets/solver_worker.h"

#include "core/model/scene_error.h"
#include "core/solve/shell_solver.h"

namespace drape {

// A pause holds the solver between two Newton iterations (the token is
// checked before each): no step completes until Resume, Step or Stop.
void SolverWorker::pause() {
  std::lock_guard lock(mutex_);
  paused_ = true;
  steps_allowed_ = 0;
  cancel_.Pause();
}

void SolverWorker::resume() {
  std::lock_guard lock(mutex_);
  paused_ = false;
  steps_allowed_ = 0;
  cancel_.Resume();
}

void SolverWorker::step() {
  std::lock_guard lock(mutex_);
  if (!paused_) return;
  ++steps_allowed_;
  cancel_.Resume();  // until the allowed step has converged (Observe)
}

void SolverWorker::stop() {
  cancel_.Cancel();  // also ends a pause
  std::lock_guard lock(mutex_);
  room_.notify_all();  // and a wait for room in the queue
}

void SolverWorker::consumed() {
  std::lock_guard lock(mutex_);
  --queued_;
  room_.notify_all();
}

StepDecision SolverWorker::Observe(const StepState& step) {
  {
    std::unique_lock lock(mutex_);
    room_.wait(lock, [&] { return queued_ < kQueueLength || cancel_.IsCancelled(); });
    ++queued_;
  }
  emit stepConverged(std::make_shared<const StepState>(step));
  std::lock_guard lock(mutex_);
  if (paused_ && steps_allowed_ > 0 && --steps_allowed_ == 0) cancel_.Pause();
  return StepDecision::kContinue;
}

void SolverWorker::run(const Scene& scene) {
  try {
    const SolverOptions options = SolverOptions::FromScene(scene.solver);
    auto solver = std::make_shared<ShellSolver>(scene, options);
    std::vector<NamedVector> last_probes;  // the final step's, as `drape run` takes them
    const SolveSummary summary = solver->Solve({[&](const StepState& s) {
                                                 last_probes = s.probes;
                                                 return Observe(s);
                                               }},
                                               &cancel_);
    if (summary.IsComplete()) emit solved(std::move(solver));
    if (summary.IsComplete() && scene.solver.error_estimate) {
      emit estimatingError();
      ErrorEstimate estimate;
      try {
        estimate = EstimateError(scene, options, last_probes, &cancel_);
      } catch (const std::exception& e) {  // a coarser mesh the scene cannot be built on
        estimate.meshes[0] = MeshName(scene);
        estimate.reason = std::string("the coarser meshes could not be solved: ") + e.what();
      }
      // The run's own result stands: only the estimate is lost.
      if (!cancel_.IsCancelled()) emit errorEstimated(estimate);
    }
    emit finished(summary);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
  }
}

}  // namespace drape
