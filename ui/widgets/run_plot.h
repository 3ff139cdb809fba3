// The live plot of a run: the load factor λ of each converged step (per
// stage, so a new stage starts again from 0), the Newton iterations it took,
// and where the number of negative pivots changed (a limit or bifurcation
// point crossed) marked on the λ curve.
#pragma once

#include <QChartView>

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
  int stabilityMarks() const;  // negative-pivot changes marked

 private:
  QLineSeries *lambda_, *iterations_;
  QScatterSeries* stability_;
  QValueAxis *steps_axis_, *lambda_axis_, *iterations_axis_;
  int last_pivots_ = 0;
  int max_iterations_ = 1;
};

}  // namespace drape
