// Which nodes something holds or loads, chosen as a user thinks of them:
// an edge, the corners, the node nearest a point, or the nodes picked in
// the viewport. One picked node becomes the point where it is (any mesh
// density finds it); several are kept by their numbers (this mesh only).
#pragma once

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

#include "core/model/scene.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace drape {

// "left edge", "corners", "point (0.1, 0) m", "3 nodes".
QString DescribeSelection(const Selection& selection);

class SelectionRuleEditor : public QObject {
  Q_OBJECT
 public:
  // Adds its rows (rule, point x and y, picked) to `form`.
  SelectionRuleEditor(QFormLayout* form, const QString& label, QWidget* parent);

  // rule: "left", "right", "bottom", "top", "corners", "point" (at x, y
  // [m]) or "picked". Empty with the reason in `problem` when the rule
  // cannot be made (nothing picked, an unknown rule).
  std::optional<Selection> selection(const QString& rule,
                                     double x,
                                     double y,
                                     QString* problem) const;
  // The rule and point the rows show.
  std::optional<Selection> current(QString* problem) const;
  // The picked nodes as a selection (see the top of this file).
  std::optional<Selection> picked(QString* problem) const;

  void setPicked(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);

 private:
  QComboBox* rule_;
  QDoubleSpinBox *x_, *y_;
  QLabel* picked_label_;
  std::vector<int> picked_;
  std::vector<std::array<double, 2>> picked_at_;
};

}  // namespace drape
