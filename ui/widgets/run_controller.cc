#include "ui/widgets/run_controller.h"

#include <QThread>

#include "ui/widgets/solver_worker.h"

namespace drape {

RunController::RunController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<drape::Scene>();
  qRegisterMetaType<drape::SolveSummary>();
  qRegisterMetaType<drape::ErrorEstimate>();
  qRegisterMetaType<std::shared_ptr<const drape::StepState>>();
  qRegisterMetaType<std::shared_ptr<drape::ShellSolver>>();
}

RunController::~RunController() {
  stop();
  if (thread_) {
    thread_->quit();
    thread_->wait();
  }
}

bool RunController::start(const Scene& scene) {
  if (worker_) return false;
  thread_ = new QThread(this);
  worker_ = new SolverWorker;
  worker_->moveToThread(thread_);
  connect(thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(
      worker_,
      &SolverWorker::stepConverged,
      this,
      [this](std::shared_ptr<const StepState> step) {
        if (worker_) worker_->consumed();
        emit stepConverged(std::move(step));
      },
      Qt::QueuedConnection);
  connect(
      worker_,
      &SolverWorker::solved,
      this,
      [this, scene](std::shared_ptr<ShellSolver> solver) { emit solved(std::move(solver), scene); },
      Qt::QueuedConnection);
  connect(worker_,
          &SolverWorker::estimatingError,
          this,
          &RunController::estimating,
          Qt::QueuedConnection);
  connect(worker_,
          &SolverWorker::errorEstimated,
          this,
          &RunController::estimated,
          Qt::QueuedConnection);
  connect(worker_, &SolverWorker::finished, this, &RunController::Finish, Qt::QueuedConnection);
  connect(
      worker_,
      &SolverWorker::failed,
      this,
      [this](const QString& message) {
        emit failed(message);
        SolveSummary summary;
        summary.termination = Termination::kInvalidInput;
        summary.message = message.toStdString();
        Finish(summary);
      },
      Qt::QueuedConnection);
  thread_->start();
  paused_ = false;
  QMetaObject::invokeMethod(
      worker_, [w = worker_, scene] { w->run(scene); }, Qt::QueuedConnection);
  return true;
}

void RunController::pauseOrResume() {
  if (!worker_) return;
  paused_ = !paused_;
  paused_ ? worker_->pause() : worker_->resume();
}

void RunController::stepOnce() {
  if (worker_ && paused_) worker_->step();
}

void RunController::stop() {
  if (worker_) worker_->stop();
}

void RunController::Finish(const SolveSummary& summary) {
  thread_->quit();
  thread_->wait();
  thread_->deleteLater();
  thread_ = nullptr;
  worker_ = nullptr;
  paused_ = false;
  emit finished(summary);
}

}  // namespace drape
