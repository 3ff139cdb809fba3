// The live plot of a run: the load factor λ of each converged step (per
// stage, so a new stage starts again from 0), the Newton iterations it took,
// and the limit and bifurcation points the path crossed and the snaps it
// made, marked on the λ curve (a bifurcation where the run switched branch,
// or followed the primary path on; a snap where the part landed).
#pragma once

#include <QChartView>

#include "core/continuation/stability_event.h"

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace drape {

struct StepState;

class RunPlot : public QChartView {
  Q_OBJECT
 public:
  explicit RunPlot(QWidget* parent = nullptr);

  void clear();
  void add(const StepState& step);

  int points() const;          // steps plotted
  int stabilityMarks() const;  // limit and bifurcation points and snaps marked

 private:
  QScatterSeries* SeriesOf(StabilityKind kind) const;

  QLineSeries *lambda_, *iterations_;
  QScatterSeries *limits_, *bifurcations_, *snaps_;
  QValueAxis *steps_axis_, *lambda_axis_, *iterations_axis_;
  int max_iterations_ = 1;
};

}  // namespace drape
