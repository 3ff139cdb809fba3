#include "ui/widgets/preview_controller.h"

#include <QThread>

#include <exception>
#include <utility>

#include "core/model/solver_preset.h"
#include "core/solve/shell_solver.h"

namespace drape {

struct PreviewController::Job {
  Scene scene;  // at the draft preset
  int generation = 0;
  std::shared_ptr<CancellationToken> token;
};

PreviewController::PreviewController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<drape::SolveSummary>();
  qRegisterMetaType<std::shared_ptr<const drape::StepState>>();
  qRegisterMetaType<std::shared_ptr<const drape::ShellModel>>();
  thread_ = new QThread(this);
  context_ = new QObject;
  context_->moveToThread(thread_);
  connect(thread_, &QThread::finished, context_, &QObject::deleteLater);
  thread_->start();
}

PreviewController::~PreviewController() {
  if (token_) token_->Cancel();
  thread_->quit();
  thread_->wait();
}

Scene PreviewController::DraftOf(const Scene& edited) {
  Scene draft = edited;
  draft.solver = WithPreset(draft.solver, SolverPreset::kDraft);
  return draft;
}

int PreviewController::request(const Scene& edited) {
  cancel();
  token_ = std::make_shared<CancellationToken>();
  busy_ = true;
  // A copy of the scene: the document may change again before the worker
  // takes the job (it then finds the job cancelled and skips it).
  Job job{DraftOf(edited), generation_, token_};
  QMetaObject::invokeMethod(
      context_, [this, job = std::move(job)] { Solve(this, job); }, Qt::QueuedConnection);
  return generation_;
}

// A new generation: signals of the old one still queued are dropped when
// they arrive (Post), and its solve stops at its next Newton iteration.
void PreviewController::cancel() {
  if (token_) token_->Cancel();
  token_.reset();
  ++generation_;
  busy_ = false;
}

// From the worker thread: `emit_if_current` runs on the GUI thread, and
// only if no request came after the job's.
void PreviewController::Post(int generation, std::function<void()> emit_if_current) {
  QMetaObject::invokeMethod(
      this,
      [this, generation, f = std::move(emit_if_current)] {
        if (generation == generation_)
          f();
        else
          ++dropped_;
      },
      Qt::QueuedConnection);
}

// On the worker thread. A job cancelled while it waited in the queue (a
// burst of edits) is skipped: only the newest of the burst is solved.
void PreviewController::Solve(PreviewController* self, const Job& job) {
  if (job.token->IsCancelled()) return;
  const int generation = job.generation;
  try {
    ShellSolver solver(job.scene, SolverOptions::FromScene(job.scene.solver));
    auto model = std::make_shared<const ShellModel>(solver.model());
    const CancellationToken& token = *job.token;
    const SolveSummary summary =
        solver.Solve({[&](const StepState& s) {
                       if (token.IsCancelled()) return StepDecision::kStop;
                       auto step = std::make_shared<const StepState>(s);
                       self->Post(generation, [self, generation, model, step] {
                         emit self->previewStep(generation, model, step);
                       });
                       return StepDecision::kContinue;
                     }},
                     &token);
    if (token.IsCancelled()) return;
    self->Post(generation, [self, generation, summary] {
      self->busy_ = false;
      emit self->previewFinished(generation, summary);
    });
  } catch (const std::exception& e) {
    const QString message = QString::fromStdString(e.what());
    self->Post(generation, [self, generation, message] {
      self->busy_ = false;
      emit self->previewFailed(generation, message);
    });
  }
}

}  // namespace drape
