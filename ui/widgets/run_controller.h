// A run of the workbench: the solver worker on its own thread, its controls
// (pause, one step, stop) and its queued signals, from start until the
// thread is joined. The window only shows what the signals bring.
#pragma once

#include <QObject>

#include <memory>

#include "core/model/scene.h"
#include "core/solve/error_estimate.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/widgets/meta_types.h"

class QThread;

namespace drape {

class SolverWorker;

class RunController : public QObject {
  Q_OBJECT
 public:
  explicit RunController(QObject* parent = nullptr);
  ~RunController() override;  // stops the run and joins its thread

  bool isRunning() const { return worker_ != nullptr; }
  bool isPaused() const { return paused_; }

  // Solves a copy of `scene` on a new thread; false while a run goes on.
  bool start(const Scene& scene);
  void pauseOrResume();
  void stepOnce();  // while paused: one more step
  void stop();      // the steps so far are kept; finished follows

 signals:
  // Each converged step, in order; the queue to the worker is freed as it
  // is delivered.
  void stepConverged(std::shared_ptr<const drape::StepState> step);
  // The run completed every stage: its solver, at the end of `scene`.
  void solved(std::shared_ptr<drape::ShellSolver> solver, const drape::Scene& scene);
  void estimating();  // the run is complete; its error estimate has begun
  void estimated(const drape::ErrorEstimate& estimate);
  void failed(const QString& message);  // the run could not start (finished follows)
  // Last: the thread is joined and isRunning() is false.
  void finished(const drape::SolveSummary& summary);

 private:
  void Finish(const SolveSummary& summary);

  QThread* thread_ = nullptr;
  SolverWorker* worker_ = nullptr;
  bool paused_ = false;
};

}  // namespace drape
