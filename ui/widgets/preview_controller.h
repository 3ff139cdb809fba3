// Instant previews (issue 20): each edit starts a background solve of the
// edited scene at the draft preset (solver_preset.h: half the mesh,
// tolerance 1e-4), streamed step by step so that a ghost can be drawn after
// the first converged step; the next edit cancels it.
//
// Generations: every request() numbers a new preview, and only signals of
// the newest request are emitted. The worker stops an obsolete solve at its
// next Newton iteration (its CancellationToken), and the GUI thread drops
// any of its steps already queued, so an obsolete preview never overwrites
// a newer one.
//
// Refinement is the workbench's normal run (RunController) at the scene's
// own settings, which the user starts or the window starts on
// previewFinished: a second background pass here would compete with it for
// the same cores and give a result the timeline would not hold.
#pragma once

#include <QObject>
#include <QString>

#include <functional>
#include <memory>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/widgets/meta_types.h"

class QThread;

namespace drape {

class PreviewController : public QObject {
  Q_OBJECT
 public:
  explicit PreviewController(QObject* parent = nullptr);
  ~PreviewController() override;  // cancels the preview and joins its thread

  // `edited` at the draft preset (its other solver settings kept), solved
  // on the worker thread; cancels the preview under way. Returns the new
  // generation, the number its signals carry.
  int request(const Scene& edited);
  // No preview's signals after this (until the next request).
  void cancel();

  int generation() const { return generation_; }
  // A request not yet finished, failed or cancelled.
  bool isBusy() const { return busy_; }
  // Signals of older generations that reached the GUI thread after a newer
  // request and were dropped (what shows the GUI-side check at work).
  int dropped() const { return dropped_; }

  // The scene a preview solves: `edited` with the draft preset.
  static Scene DraftOf(const Scene& edited);

 signals:
  // Each converged step of the newest preview, in order, with the model
  // (its draft mesh, coarser than the scene's) the state lives on.
  void previewStep(int generation,
                   std::shared_ptr<const drape::ShellModel> model,
                   std::shared_ptr<const drape::StepState> step);
  // The newest preview's solve ended (complete, or stopped short).
  void previewFinished(int generation, const drape::SolveSummary& summary);
  // The newest preview's scene could not be modelled (the message says why).
  void previewFailed(int generation, const QString& message);

 private:
  struct Job;
  static void Solve(PreviewController* self, const Job& job);
  void Post(int generation, std::function<void()> emit_if_current);

  QThread* thread_ = nullptr;
  QObject* context_ = nullptr;                // lives on thread_: runs the jobs
  std::shared_ptr<CancellationToken> token_;  // the newest preview's
  int generation_ = 0;                        // written and read on the GUI thread only
  bool busy_ = false;
  int dropped_ = 0;
};

}  // namespace drape

Q_DECLARE_METATYPE(std::shared_ptr<const drape::ShellModel>)
