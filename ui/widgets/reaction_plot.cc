#include "ui/widgets/reaction_plot.h"

#include <QChart>
#include <QComboBox>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

#include <algorithm>

#include "core/model/scene.h"
#include "core/solve/step_state.h"

namespace drape {
namespace {

const char* Title(ReactionPlot::Mode mode) {
  switch (mode) {
    case ReactionPlot::Mode::kMagnitude:
      return "support and gripper reactions: |F|";
    case ReactionPlot::Mode::kX:
      return "support and gripper reactions: F_x";
    case ReactionPlot::Mode::kY:
      return "support and gripper reactions: F_y";
    case ReactionPlot::Mode::kZ:
      return "support and gripper reactions: F_z";
  }
  return "";
}

}  // namespace

ReactionPlot::ReactionPlot(QWidget* parent) : QChartView(parent) {
  auto* chart = new QChart;
  // The legend beside the plot: the dock is low, the lines need its height.
  chart->legend()->setAlignment(Qt::AlignRight);
  steps_ = new QValueAxis;
  steps_->setTitleText("step");
  steps_->setLabelFormat("%d");
  forces_ = new QValueAxis;
  forces_->setTitleText("reaction [N]");  // setUnitSystem names another unit
  forces_->setLabelFormat("%.3g");
  chart->addAxis(steps_, Qt::AlignBottom);
  chart->addAxis(forces_, Qt::AlignLeft);
  // The timeline's step: a dashed vertical line over the whole height.
  marker_ = new QLineSeries;
  marker_->setName("shown step");
  QPen pen(QColor(90, 90, 90));
  pen.setStyle(Qt::DashLine);
  pen.setWidthF(1.5);
  marker_->setPen(pen);
  chart->addSeries(marker_);
  marker_->attachAxis(steps_);
  marker_->attachAxis(forces_);
  for (QLegendMarker* m : chart->legend()->markers(marker_)) m->setVisible(false);
  setChart(chart);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(230);
  mode_box_ = new QComboBox(this);
  mode_box_->setObjectName("reactionMode");
  mode_box_->addItems({"|F|", "F_x", "F_y", "F_z"});
  mode_box_->setToolTip("What the plot shows of each reaction: its magnitude or one component");
  mode_box_->move(6, 6);
  connect(mode_box_, &QComboBox::currentIndexChanged, this, [this](int i) {
    setMode(static_cast<Mode>(i));
  });
  setMode(Mode::kMagnitude);
  clear();
}

void ReactionPlot::setScene(const Scene& scene) {
  released_at_.clear();
  for (size_t s = 0; s < scene.stages.size(); ++s)
    for (const std::string& name : scene.stages[s].release)
      released_at_.emplace(name, static_cast<int>(s));  // the first release holds
}

void ReactionPlot::clear() {
  for (Hold& h : holds_) {
    chart()->removeSeries(h.series);
    delete h.series;
  }
  holds_.clear();
  last_step_ = current_step_ = 0;
  low_ = high_ = 0;
  empty_ = true;
  FitAxes();
}

void ReactionPlot::add(const StepState& step) {
  for (size_t i = holds_.size(); i < step.reactions.size(); ++i) {
    Hold h;
    h.series = new QLineSeries;
    h.series->setName(QString::fromStdString(step.reactions[i].name));
    chart()->addSeries(h.series);
    h.series->attachAxis(steps_);
    h.series->attachAxis(forces_);
    holds_.push_back(std::move(h));
  }
  for (size_t i = 0; i < step.reactions.size(); ++i) {
    const NamedVector& r = step.reactions[i];
    const auto released = released_at_.find(r.name);
    if (released != released_at_.end() && step.stage >= released->second) continue;
    Hold& h = holds_[i];
    h.steps.push_back(step.step);
    h.forces.push_back(r.value);
    const double v = Plotted(r.value);
    h.series->append(step.step, v);
    Extend(v);
  }
  last_step_ = std::max(last_step_, step.step);
  FitAxes();
}

void ReactionPlot::setCurrentStep(int step) {
  current_step_ = step;
  PlaceMarker();
}

void ReactionPlot::setMode(Mode mode) {
  mode_ = mode;
  if (mode_box_->currentIndex() != static_cast<int>(mode)) {
    const QSignalBlocker block(mode_box_);
    mode_box_->setCurrentIndex(static_cast<int>(mode));
  }
  chart()->setTitle(Title(mode));
  Replot();
}

QString ReactionPlot::holdName(int hold) const {
  return holds_.at(static_cast<size_t>(hold)).series->name();
}

int ReactionPlot::points(int hold) const {
  return hold >= 0 && hold < holds() ? static_cast<int>(holds_[hold].series->count()) : 0;
}

int ReactionPlot::step(int hold, int point) const {
  return holds_.at(static_cast<size_t>(hold)).steps.at(static_cast<size_t>(point));
}

double ReactionPlot::value(int hold, int point) const {
  return holds_.at(static_cast<size_t>(hold)).series->at(point).y();
}

Eigen::Vector3d ReactionPlot::force(int hold, int point) const {
  return holds_.at(static_cast<size_t>(hold)).forces.at(static_cast<size_t>(point));
}

double ReactionPlot::markerStep() const {
  return marker_->count() > 0 ? marker_->at(0).x() : -1;
}

double ReactionPlot::Plotted(const Eigen::Vector3d& si) const {
  const Eigen::Vector3d force = si / UnitFor(Measure::kForce, units_).si_factor;
  switch (mode_) {
    case Mode::kMagnitude:
      return force.norm();
    case Mode::kX:
      return force.x();
    case Mode::kY:
      return force.y();
    case Mode::kZ:
      return force.z();
  }
  return 0;
}

void ReactionPlot::setUnitSystem(UnitSystem system) {
  units_ = system;
  forces_->setTitleText(
      QString("reaction [%1]").arg(QString::fromStdString(UnitFor(Measure::kForce, system).label)));
  Replot();
}

void ReactionPlot::Replot() {
  low_ = high_ = 0;
  empty_ = true;
  for (Hold& h : holds_) {
    QList<QPointF> points;
    points.reserve(static_cast<qsizetype>(h.steps.size()));
    for (size_t k = 0; k < h.steps.size(); ++k) {
      const double v = Plotted(h.forces[k]);
      points.append(QPointF(h.steps[k], v));
      Extend(v);
    }
    h.series->replace(points);
  }
  FitAxes();
}

// The steps from 0 to the latest (at least 10); the forces from 0 (a
// magnitude) or their least to their largest, with a margin.
void ReactionPlot::FitAxes() {
  const double low = std::min(low_, 0.0), high = std::max(high_, 0.0);
  const double margin = std::max(1e-9, 0.05 * (high - low));
  forces_->setRange(low < 0 ? low - margin : 0, high + margin);
  forces_->applyNiceNumbers();  // round ticks (the range may widen a little)
  steps_->setRange(0, std::max(10, last_step_));
  PlaceMarker();
}

// Over the whole height; no line before anything is plotted.
void ReactionPlot::PlaceMarker() {
  if (empty_) return marker_->clear();
  marker_->replace(
      {QPointF(current_step_, forces_->min()), QPointF(current_step_, forces_->max())});
}

void ReactionPlot::Extend(double value) {
  low_ = empty_ ? value : std::min(low_, value);
  high_ = empty_ ? value : std::max(high_, value);
  empty_ = false;
}

}  // namespace drape
