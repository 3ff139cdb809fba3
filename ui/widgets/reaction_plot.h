// The live plot of what each support and gripper carries along a run: the
// reaction it exerts on the fabric (StepState::reactions, [N]) against the
// step, one line per hold in the scene's order, as its magnitude |F| or one
// component (a combo box in the corner), with a vertical line at the step
// the timeline shows. A gripper released in a stage (the scene's
// stages[].release) gets no points from that stage on: its line ends where
// the robot lets go. The plot only draws what the steps say; it computes no
// force itself.
#pragma once

#include <Eigen/Core>
#include <QChartView>

#include <map>
#include <string>
#include <vector>

#include "core/model/unit_system.h"

class QComboBox;
class QLineSeries;
class QValueAxis;

namespace drape {

struct Scene;
struct StepState;

class ReactionPlot : public QChartView {
  Q_OBJECT
 public:
  enum class Mode { kMagnitude, kX, kY, kZ };  // the combo box's entries, in order

  explicit ReactionPlot(QWidget* parent = nullptr);

  // Which gripper each stage releases (set before the run's first step).
  void setScene(const Scene& scene);
  void clear();
  void add(const StepState& step);
  // The vertical line at `step` (the timeline's; 0 is the reference state).
  void setCurrentStep(int step);
  void setMode(Mode mode);
  Mode mode() const { return mode_; }
  // Forces in `system`'s unit (N, gf, oz) from now on: the axis, the points.
  void setUnitSystem(UnitSystem system);
  QValueAxis* forceAxis() const { return forces_; }

  // Holds plotted (supports, then grippers), and for hold `hold` (in the
  // order of StepState::reactions): its name, the points plotted, and point
  // `point`'s step, plotted value (in the current mode and unit) and force
  // vector [N].
  int holds() const { return static_cast<int>(holds_.size()); }
  QString holdName(int hold) const;
  int points(int hold) const;
  int step(int hold, int point) const;
  double value(int hold, int point) const;
  Eigen::Vector3d force(int hold, int point) const;
  // The marker line's step, or -1 while there is none (nothing plotted).
  double markerStep() const;
  QComboBox* modeBox() const { return mode_box_; }

 private:
  struct Hold {
    QLineSeries* series = nullptr;
    std::vector<int> steps;
    std::vector<Eigen::Vector3d> forces;
  };
  double Plotted(const Eigen::Vector3d& force) const;
  void Replot();  // every series from the forces, in the current mode
  void FitAxes();
  void PlaceMarker();
  void Extend(double value);  // the range plotted takes in `value`

  std::vector<Hold> holds_;
  std::map<std::string, int> released_at_;  // gripper → the stage that releases it
  QLineSeries* marker_ = nullptr;
  QValueAxis *steps_ = nullptr, *forces_ = nullptr;
  QComboBox* mode_box_ = nullptr;
  Mode mode_ = Mode::kMagnitude;
  UnitSystem units_ = UnitSystem::kSI;
  double low_ = 0, high_ = 0;  // the values plotted
  bool empty_ = true;          // nothing plotted yet
  int last_step_ = 0;          // the latest step plotted
  int current_step_ = 0;       // where the marker stands
};

}  // namespace drape
