// The run's error estimate (solver.error_estimate) in a status bar, beside
// the run's summary: core's one-line Describe(), cut short to the room the
// summary leaves (the whole line, each probe's error, GCI and extrapolated
// position in the tooltip); the reason, never a number, outside the
// asymptotic range.
#pragma once

#include <QLabel>

#include <optional>

#include "core/solve/error_estimate.h"

class QStatusBar;

namespace drape {

class ErrorEstimateLabel : public QLabel {
  Q_OBJECT
 public:
  // Stands at the bar's right (a permanent widget), hidden until shown.
  explicit ErrorEstimateLabel(QStatusBar* bar);

  void clear();           // a new run or an edit: no estimate
  void showEstimating();  // the run is done, the coarse meshes are solving
  void showEstimate(const ErrorEstimate& estimate);
  void showStopped();  // Stop ended the estimate before it was done
  // The errors in `system`'s error unit (ErrorUnit: mm, or in); the shown
  // estimate is said again in it.
  void setUnitSystem(UnitSystem system);
  // The last estimate shown; empty while none came.
  const std::optional<ErrorEstimate>& estimate() const { return estimate_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void Show(const QString& text, const QString& tooltip);
  void Fit();

  QStatusBar* bar_;
  QString text_;  // before eliding
  std::optional<ErrorEstimate> estimate_;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
