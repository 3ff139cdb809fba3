#include "ui/widgets/run_monitor.h"

#include <QWidget>

#include "ui/widgets/error_estimate_label.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/run_controller.h"
#include "ui/widgets/run_plot.h"
#include "ui/widgets/view_controller.h"

namespace drape {

RunMonitor::RunMonitor(ViewController* view, QWidget* window, QStatusBar* bar, QObject* parent)
    : QObject(parent), view_(view) {
  qRegisterMetaType<drape::Scene>();
  qRegisterMetaType<drape::SolveSummary>();
  qRegisterMetaType<drape::ErrorEstimate>();
  qRegisterMetaType<std::shared_ptr<const drape::StepState>>();
  runs_ = new RunController(this);
  plot_ = new RunPlot(window);
  probe_plot_ = new ProbePlot(window);
  residual_plot_ = new ResidualPlot(window);
  reaction_plot_ = new ReactionPlot(window);
  // The run's error estimate stands at the status bar's right, beside the
  // summary the bar shows when the run is done, and stays there when other
  // messages replace that summary.
  estimate_label_ = new ErrorEstimateLabel(bar);
  connect(runs_, &RunController::stepConverged, this, &RunMonitor::OnStep);
  // The run is complete; the worker solves the scene again on meshes 2h
  // and 4h (Stop ends that too).
  connect(runs_, &RunController::estimating, this, [this] {
    estimating_ = true;
    emit message("estimating the error on meshes 2 and 4 times coarser…");
    estimate_label_->showEstimating();
    emit controlsChanged();
  });
  connect(runs_, &RunController::estimated, estimate_label_, &ErrorEstimateLabel::showEstimate);
  connect(runs_, &RunController::failed, this, &RunMonitor::failed);
  connect(runs_, &RunController::finished, this, [this](const SolveSummary& summary) {
    if (estimating_ && !estimate_label_->estimate()) estimate_label_->showStopped();
    estimating_ = false;
    emit message(QString::fromStdString(summary.BriefReport()));
    emit finished(summary);
  });
  // The timeline's index is the step's number.
  connect(view_, &ViewController::stepShown, reaction_plot_, &ReactionPlot::setCurrentStep);
}

RunMonitor::~RunMonitor() {
  delete runs_;  // before the plots and the view the run's signals go to
  runs_ = nullptr;
}

bool RunMonitor::isRunning() const {
  return runs_ && runs_->isRunning();
}

bool RunMonitor::isPaused() const {
  return runs_ && runs_->isPaused();
}

bool RunMonitor::start(const Scene& scene) {
  if (isRunning()) return false;
  view_->clearSteps();
  plot_->clear();
  probe_plot_->clear();
  residual_plot_->clear();
  reaction_plot_->clear();
  reaction_plot_->setScene(scene);
  estimating_ = false;
  estimate_label_->clear();
  runs_->start(scene);
  emit message("running…");
  return true;
}

void RunMonitor::pauseOrResume() {
  runs_->pauseOrResume();
  emit controlsChanged();
}

void RunMonitor::stepOnce() {
  runs_->stepOnce();
}

void RunMonitor::setUnitSystem(UnitSystem system) {
  probe_plot_->setUnitSystem(system);
  reaction_plot_->setUnitSystem(system);
  estimate_label_->setUnitSystem(system);
}

void RunMonitor::stop() {
  runs_->stop();
}

// Every step is kept and plotted; the view draws the newest.
void RunMonitor::OnStep(std::shared_ptr<const StepState> step) {
  plot_->add(*step);
  probe_plot_->add(*step);
  residual_plot_->add(*step);
  reaction_plot_->add(*step);
  view_->addStep(std::move(step));
}

}  // namespace drape
