#include "ui/widgets/error_estimate_label.h"

#include <QEvent>
#include <QStatusBar>

#include <algorithm>

namespace drape {

ErrorEstimateLabel::ErrorEstimateLabel(QStatusBar* bar) : QLabel(bar), bar_(bar) {
  setObjectName("errorEstimate");
  setMinimumWidth(1);  // elided, never widens the window
  hide();
  bar->addPermanentWidget(this);
  connect(bar, &QStatusBar::messageChanged, this, [this] { Fit(); });
  bar->installEventFilter(this);  // its resizes
}

void ErrorEstimateLabel::clear() {
  estimate_.reset();
  Show({}, {});
}

void ErrorEstimateLabel::showEstimating() {
  estimate_.reset();
  Show("estimating the error…",
       "The run is complete: the scene is solved again on meshes 2 and 4 times coarser to "
       "estimate its error (Richardson). Stop ends the estimate.");
}

void ErrorEstimateLabel::showEstimate(const ErrorEstimate& estimate) {
  estimate_ = estimate;
  const DisplayUnit unit = ErrorUnit(units_);
  const QString line = QString::fromStdString(Describe(estimate, unit));
  QString tooltip = line;
  if (estimate.in_asymptotic_range) {
    tooltip += QString("\n\nobserved order %1; per probe:").arg(estimate.order, 0, 'f', 2);
    const QString label = QString::fromStdString(unit.label);
    auto in_unit = [&](double si) { return QString::number(si / unit.si_factor, 'g', 3); };
    auto at = [&](double si) { return QString::number(si / unit.si_factor, 'g', 6); };
    for (const ProbeErrorEstimate& p : estimate.probes)
      tooltip += QString("\n%1: error %2 %3, GCI ±%4 %3, extrapolated (%5, %6, %7) %3")
                     .arg(QString::fromStdString(p.name),
                          in_unit(p.error),
                          label,
                          in_unit(p.gci),
                          at(p.extrapolated.x()),
                          at(p.extrapolated.y()),
                          at(p.extrapolated.z()));
  }
  Show(line, tooltip);
}

void ErrorEstimateLabel::setUnitSystem(UnitSystem system) {
  units_ = system;
  if (estimate_) showEstimate(*estimate_);
}

void ErrorEstimateLabel::showStopped() {
  Show("error estimate: stopped before it was done",
       "Stop ended the estimate; the run's own result is complete.");
}

bool ErrorEstimateLabel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == bar_ && event->type() == QEvent::Resize) Fit();
  return QLabel::eventFilter(watched, event);
}

void ErrorEstimateLabel::Show(const QString& text, const QString& tooltip) {
  text_ = text;
  setToolTip(tooltip);
  setVisible(!text.isEmpty());
  Fit();
}

// What the bar's message (the run's summary) leaves, and at least a third
// of the bar.
void ErrorEstimateLabel::Fit() {
  const int message = bar_->fontMetrics().horizontalAdvance(bar_->currentMessage());
  const int room = std::max(bar_->width() / 3, bar_->width() - message - 48);
  setText(fontMetrics().elidedText(text_, Qt::ElideRight, room));
}

}  // namespace drape
