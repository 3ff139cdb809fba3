#include "ui/widgets/probe_plot.h"

#include <QChart>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

#include "core/solve/step_state.h"

namespace drape {

ProbePlot::ProbePlot(QWidget* parent) : QChartView(parent) {
  auto* chart = new QChart;
  chart->setTitle("probe heights");
  chart->legend()->setAlignment(Qt::AlignBottom);
  steps_ = new QValueAxis;
  steps_->setTitleText("step");
  steps_->setLabelFormat("%d");
  heights_ = new QValueAxis;
  heights_->setTitleText("z [m]");  // setUnitSystem names another unit
  chart->addAxis(steps_, Qt::AlignBottom);
  chart->addAxis(heights_, Qt::AlignLeft);
  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(230);
  clear();
}

void ProbePlot::clear() {
  for (QLineSeries* s : series_) {
    chart()->removeSeries(s);
    delete s;
  }
  series_.clear();
  si_.clear();
  steps_->setRange(0, 10);
  heights_->setRange(-0.01 / Unit(), 0.01 / Unit());  // ±1 cm
  low_ = high_ = 0;
  empty_ = true;
}

void ProbePlot::add(const StepState& step) {
  for (size_t i = series_.size(); i < step.probes.size(); ++i) {
    auto* s = new QLineSeries;
    s->setName(QString::fromStdString(step.probes[i].name));
    chart()->addSeries(s);
    s->attachAxis(steps_);
    s->attachAxis(heights_);
    series_.push_back(s);
    si_.emplace_back();
  }
  for (size_t i = 0; i < step.probes.size(); ++i) {
    const double z = step.probes[i].value.z();
    low_ = empty_ ? z : std::min(low_, z);
    high_ = empty_ ? z : std::max(high_, z);
    empty_ = false;
    si_[i].append(QPointF(step.step, z));
    series_[i]->append(step.step, z / Unit());
  }
  SetHeightRange();
  steps_->setRange(0, std::max(10, step.step));
}

void ProbePlot::SetHeightRange() {
  const double margin = std::max(1e-3, 0.05 * (high_ - low_));  // [m]
  heights_->setRange((low_ - margin) / Unit(), (high_ + margin) / Unit());
}

void ProbePlot::setUnitSystem(UnitSystem system) {
  units_ = system;
  const DisplayUnit unit = UnitFor(Measure::kLength, system);
  heights_->setTitleText(QString("z [%1]").arg(QString::fromStdString(unit.label)));
  for (size_t i = 0; i < series_.size(); ++i) {
    QList<QPointF> shown = si_[i];
    for (QPointF& p : shown) p.setY(p.y() / unit.si_factor);
    series_[i]->replace(shown);
  }
  if (!empty_) SetHeightRange();
}

int ProbePlot::points(int probe) const {
  return probe < static_cast<int>(series_.size()) ? static_cast<int>(series_[probe]->count()) : 0;
}

double ProbePlot::lastHeight(int probe) const {
  return si_.at(static_cast<size_t>(probe)).back().y();
}

ResidualPlot::ResidualPlot(QWidget* parent) : QChartView(parent) {
  auto* chart = new QChart;
  chart->setTitle("Newton residuals of the latest step");
  chart->legend()->hide();
  residuals_ = new QLineSeries;
  residuals_->setPointsVisible(true);
  chart->addSeries(residuals_);
  iterations_ = new QValueAxis;
  iterations_->setTitleText("iteration");
  iterations_->setLabelFormat("%d");
  norms_ = new QLogValueAxis;
  norms_->setTitleText("‖R‖/‖R₀‖");
  norms_->setLabelFormat("%.0e");
  norms_->setBase(10);
  chart->addAxis(iterations_, Qt::AlignBottom);
  chart->addAxis(norms_, Qt::AlignLeft);
  residuals_->attachAxis(iterations_);
  residuals_->attachAxis(norms_);
  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(230);
  clear();
}

void ResidualPlot::clear() {
  residuals_->clear();
  iterations_->setRange(0, 5);
  norms_->setRange(1e-12, 1);
}

void ResidualPlot::add(const StepState& step) {
  residuals_->clear();
  double low = 1;
  for (size_t k = 0; k < step.residuals.size(); ++k) {
    // A log axis cannot show 0: an exact zero is drawn at the floor.
    const double r = std::max(step.residuals[k], 1e-16);
    residuals_->append(static_cast<double>(k), r);
    low = std::min(low, r);
  }
  iterations_->setRange(0, std::max<double>(5, static_cast<double>(step.residuals.size())));
  norms_->setRange(std::pow(10.0, std::floor(std::log10(low))), 10);
}

int ResidualPlot::points() const {
  return static_cast<int>(residuals_->count());
}

}  // namespace drape
