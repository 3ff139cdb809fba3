#include "ui/widgets/run_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

#include "core/solve/step_state.h"

namespace drape {

RunPlot::RunPlot(QWidget* parent) : QChartView(parent) {
  auto* chart = new QChart;
  chart->legend()->setAlignment(Qt::AlignBottom);
  lambda_ = new QLineSeries;
  lambda_->setName("share of the stage done (λ)");
  iterations_ = new QLineSeries;
  iterations_->setName("Newton iterations");
  limits_ = new QScatterSeries;
  limits_->setName("limit point");
  limits_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  limits_->setMarkerSize(9);
  limits_->setColor(QColor(230, 140, 20));
  bifurcations_ = new QScatterSeries;
  bifurcations_->setName("bifurcation");
  bifurcations_->setMarkerSize(10);
  bifurcations_->setColor(QColor(200, 30, 30));
  snaps_ = new QScatterSeries;
  snaps_->setName("snap");
  snaps_->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
  snaps_->setMarkerSize(11);
  snaps_->setColor(QColor(120, 40, 170));
  chart->addSeries(lambda_);
  chart->addSeries(iterations_);
  chart->addSeries(limits_);
  chart->addSeries(bifurcations_);
  chart->addSeries(snaps_);
  steps_axis_ = new QValueAxis;
  steps_axis_->setTitleText("step");
  steps_axis_->setLabelFormat("%d");
  lambda_axis_ = new QValueAxis;
  lambda_axis_->setTitleText("λ");
  lambda_axis_->setRange(0, 1);
  iterations_axis_ = new QValueAxis;
  iterations_axis_->setTitleText("iterations");
  iterations_axis_->setLabelFormat("%d");
  chart->addAxis(steps_axis_, Qt::AlignBottom);
  chart->addAxis(lambda_axis_, Qt::AlignLeft);
  chart->addAxis(iterations_axis_, Qt::AlignRight);
  for (QAbstractSeries* s : {static_cast<QAbstractSeries*>(lambda_),
                             static_cast<QAbstractSeries*>(limits_),
                             static_cast<QAbstractSeries*>(bifurcations_),
                             static_cast<QAbstractSeries*>(snaps_)}) {
    s->attachAxis(steps_axis_);
    s->attachAxis(lambda_axis_);
  }
  iterations_->attachAxis(steps_axis_);
  iterations_->attachAxis(iterations_axis_);
  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(230);
  clear();
}

void RunPlot::clear() {
  lambda_->clear();
  iterations_->clear();
  limits_->clear();
  bifurcations_->clear();
  snaps_->clear();
  max_iterations_ = 1;
  steps_axis_->setRange(0, 10);
  iterations_axis_->setRange(0, 10);
}

void RunPlot::add(const StepState& step) {
  lambda_->append(step.step, step.lambda);
  iterations_->append(step.step, step.iterations);
  if (step.stability_event) SeriesOf(step.stability_event->kind)->append(step.step, step.lambda);
  max_iterations_ = std::max(max_iterations_, step.iterations);
  steps_axis_->setRange(0, std::max(10, step.step));
  iterations_axis_->setRange(0, std::max(10, max_iterations_));
}

int RunPlot::points() const {
  return static_cast<int>(lambda_->count());
}

int RunPlot::stabilityMarks() const {
  return static_cast<int>(limits_->count() + bifurcations_->count() + snaps_->count());
}

QScatterSeries* RunPlot::SeriesOf(StabilityKind kind) const {
  switch (kind) {
    case StabilityKind::kLimit:
      return limits_;
    case StabilityKind::kBifurcation:
      return bifurcations_;
    case StabilityKind::kSnap:
      return snaps_;
  }
  return bifurcations_;
}

}  // namespace drape
