#include "ui/widgets/solver_worker.h"

#include "core/model/scene_error.h"
#include "core/solve/shell_solver.h"

namespace drape {

void SolverWorker::pause() {
  std::lock_guard lock(mutex_);
  paused_ = true;
  steps_allowed_ = 0;
}

void SolverWorker::resume() {
  {
    std::lock_guard lock(mutex_);
    paused_ = false;
  }
  wake_.notify_all();
}

void SolverWorker::step() {
  {
    std::lock_guard lock(mutex_);
    ++steps_allowed_;
  }
  wake_.notify_all();
}

void SolverWorker::stop() {
  cancel_.Cancel();
  resume();
}

StepDecision SolverWorker::Observe(const StepState& step) {
  emit stepConverged(std::make_shared<const StepState>(step));
  // Paused: hold the solver between steps until resumed, stepped or stopped.
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [&] { return !paused_ || steps_allowed_ > 0 || cancel_.IsCancelled(); });
  if (paused_ && steps_allowed_ > 0) --steps_allowed_;
  return StepDecision::kContinue;
}

void SolverWorker::run(const Scene& scene) {
  try {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    const SolveSummary summary =
        solver.Solve({[this](const StepState& s) { return Observe(s); }}, &cancel_);
    emit finished(summary);
  } catch (const std::exception& e) {
    emit failed(QString::fromStdString(e.what()));
  }
}

}  // namespace drape
