// The live plots of a run beside λ: the height z of each probe over the
// steps, and the Newton residual ‖R‖/‖R₀‖ of each iteration of the latest
// step on a log scale (so quadratic convergence, or its loss, shows).
#pragma once

#include <QChartView>

#include <vector>

#include "core/model/unit_system.h"

class QLineSeries;
class QLogValueAxis;
class QValueAxis;

namespace drape {

struct StepState;

class ProbePlot : public QChartView {
  Q_OBJECT
 public:
  explicit ProbePlot(QWidget* parent = nullptr);

  void clear();
  void add(const StepState& step);
  // Points plotted for probe `i` (in the scene's order).
  int points(int probe) const;
  double lastHeight(int probe) const;  // [m]
  // Heights (axis, points, tooltips) in `system`'s length unit from now on.
  void setUnitSystem(UnitSystem system);
  QValueAxis* heightAxis() const { return heights_; }

 private:
  void SetHeightRange();
  double Unit() const { return UnitFor(Measure::kLength, units_).si_factor; }

  std::vector<QLineSeries*> series_;
  std::vector<QList<QPointF>> si_;  // per probe: (step, z [m]), for another unit
  UnitSystem units_ = UnitSystem::kSI;
  QValueAxis *steps_, *heights_;
  double low_ = 0, high_ = 0;  // the heights plotted so far
  bool empty_ = true;
};

class ResidualPlot : public QChartView {
  Q_OBJECT
 public:
  explicit ResidualPlot(QWidget* parent = nullptr);

  void clear();
  // Shows the residual history of `step` (replacing the one before).
  void add(const StepState& step);
  int points() const;

 private:
  QLineSeries* residuals_;
  QValueAxis* iterations_;
  QLogValueAxis* norms_;
};

}  // namespace drape
