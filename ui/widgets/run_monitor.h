// A run as the workbench shows it: the RunController's run of the accepted
// scene, each converged step to the plots (run, probes, residuals,
// reactions) and to the view's timeline, the error estimate beside the
// summary in the status bar, and the summary when it ends.
#pragma once

#include <QObject>

#include <memory>

#include "core/model/scene.h"
#include "core/model/unit_system.h"
#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"
#include "ui/widgets/meta_types.h"

class QStatusBar;
class QWidget;

namespace drape {

class ErrorEstimateLabel;
class ProbePlot;
class ReactionPlot;
class ResidualPlot;
class RunController;
class RunPlot;
class ViewController;

class RunMonitor : public QObject {
  Q_OBJECT
 public:
  // The plots are made as children of `window` (which docks them), the
  // estimate's label on `bar`.
  RunMonitor(ViewController* view, QWidget* window, QStatusBar* bar, QObject* parent = nullptr);
  ~RunMonitor() override;  // stops the run and joins its thread

  RunPlot* plot() const { return plot_; }
  ProbePlot* probePlot() const { return probe_plot_; }
  ResidualPlot* residualPlot() const { return residual_plot_; }
  ReactionPlot* reactionPlot() const { return reaction_plot_; }
  ErrorEstimateLabel* estimateLabel() const { return estimate_label_; }
  RunController* controller() const { return runs_; }

  bool isRunning() const;
  bool isPaused() const;
  // The run is done and its error estimate is under way.
  bool isEstimating() const { return estimating_; }

  // Clears the plots and the view's steps and solves `scene` on the
  // worker's thread; false while a run goes on.
  bool start(const Scene& scene);
  void pauseOrResume();
  void stepOnce();
  void stop();
  // The probe and reaction plots and the error estimate in `system`.
  void setUnitSystem(UnitSystem system);

 signals:
  void controlsChanged();  // paused, resumed or estimating: the controls follow
  void finished(const drape::SolveSummary& summary);  // the thread is joined
  void message(const QString& text);
  void failed(const QString& message);  // the run could not start

 private:
  void OnStep(std::shared_ptr<const StepState> step);

  ViewController* view_;
  RunController* runs_ = nullptr;
  RunPlot* plot_ = nullptr;
  ProbePlot* probe_plot_ = nullptr;
  ResidualPlot* residual_plot_ = nullptr;
  ReactionPlot* reaction_plot_ = nullptr;
  ErrorEstimateLabel* estimate_label_ = nullptr;
  bool estimating_ = false;
};

}  // namespace drape
