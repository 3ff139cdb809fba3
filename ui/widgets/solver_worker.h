// The solver on a worker thread: core's ShellSolver, driven through its
// observer and cancellation token, with every converged step sent to the
// GUI thread as a queued signal (none lost: the timeline keeps them all).
// The queue is bounded: when the GUI thread has kQueueLength steps not yet
// taken (consumed()), the solver waits, so a fast solver cannot bury the
// GUI in events. After a complete run of a scene with solver.error_estimate,
// the worker estimates the run's error with core's EstimateError (the scene
// on meshes 2 and 4 times coarser), under the run's own token: Stop ends
// the estimate too, and Pause holds it.
#pragma once

#include <QObject>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>

#include "core/model/scene.h"
#include "core/solve/error_estimate.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/widgets/meta_types.h"

namespace drape {

class SolverWorker : public QObject {
  Q_OBJECT
 public:
  // Thread-safe controls, called from the GUI thread; each takes effect
  // before the solver's next Newton iteration.
  void pause();
  void resume();
  void step();  // while paused: let one more step through
  void stop();  // steps so far are kept
  // The GUI thread has taken one step off the queue.
  void consumed();

  static constexpr int kQueueLength = 32;

 public slots:
  // Runs the whole scene; emits stepConverged per step, then (complete,
  // with solver.error_estimate) estimatingError and errorEstimated, then
  // finished. A stopped estimate emits no errorEstimated.
  void run(const drape::Scene& scene);

 signals:
  void stepConverged(std::shared_ptr<const drape::StepState> step);
  // A run that completed every stage hands its solver over (before the
  // estimate and finished): the workbench drags grippers from its end. The
  // worker no longer touches it.
  void solved(std::shared_ptr<drape::ShellSolver> solver);
  void estimatingError();  // the run is complete; its estimate has begun
  void errorEstimated(const drape::ErrorEstimate& estimate);
  void finished(const drape::SolveSummary& summary);
  void failed(const QString& message);

 private:
  StepDecision Observe(const StepState& step);

  CancellationToken cancel_;  // stops and pauses the solver
  std::mutex mutex_;
  std::condition_variable room_;  // in the queue
  int queued_ = 0;                // steps sent, not yet consumed
  bool paused_ = false;
  int steps_allowed_ = 0;  // while paused
};

}  // namespace drape
