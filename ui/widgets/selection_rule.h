// Which nodes something holds or loads, chosen as a user thinks of them:
// an edge, the corners, the node nearest a point, every node within a
// radius of a point, or the nodes picked in the viewport. One picked node becomes the point where
// it is (any mesh density finds it); several are kept by their numbers (this mesh only).
#pragma once

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

#include "core/model/scene.h"
#include "core/model/unit_system.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace drape {

class SceneDocument;

// "left edge", "corners", "point (10 cm, 0)", "line (0, 0) to (20 cm, 0)",
// "3 nodes": coordinates in `system`'s unit of length.
QString DescribeSelection(const Selection& selection, UnitSystem system = UnitSystem::kSI);

class SelectionRuleEditor : public QObject {
  Q_OBJECT
 public:
  // Adds its rows (rule, point "x, y", picked) to `form`.
  SelectionRuleEditor(QFormLayout* form, const QString& label, QWidget* parent);

  // rule: "left", "right", "bottom", "top", "corners", "point" (at x, y
  // [m]), "circle" (centre x, y [m], the radius as the radius row says),
  // "notch", "drill hole", "internal line" (a pattern piece's, the number
  // the mark row says) or "picked". Empty with the reason in `problem` when the rule
  // cannot be made (nothing picked, an unknown rule).
  std::optional<Selection> selection(const QString& rule,
                                     double x,
                                     double y,
                                     QString* problem) const;
  // The rule and point the rows show; the point is typed "x, y" in any
  // unit of length the scene reader takes ("2 in, 0"; a plain number is m).
  std::optional<Selection> current(QString* problem) const;
  // The picked nodes as a selection (see the top of this file).
  std::optional<Selection> picked(QString* problem) const;

  void setPicked(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);
  // The rows show `selection` (an edge, the corners, a point, a circle; other shapes
  // leave them as they are).
  void show(const Selection& selection);
  // The point shown in `system`'s unit of length (typing takes any unit).
  void setUnitSystem(UnitSystem system);
  // The marks row lists what `fabric`'s pattern piece has to hold by:
  // "FRONT: 4 notches, 2 drill holes, 1 internal line".
  void setFabric(const Fabric& fabric);
  // The marks row follows `document`'s fabric from now on.
  void followFabric(SceneDocument* document);

  QComboBox* rule() const { return rule_; }
  QLineEdit* point() const { return point_; }
  QLineEdit* radius() const { return radius_; }
  QSpinBox* mark() const { return mark_; }
  QLabel* marks() const { return marks_; }

 private:
  QComboBox* rule_;
  QLineEdit* point_;
  QLineEdit* radius_;
  QSpinBox* mark_;
  QLabel* marks_;
  UnitSystem units_ = UnitSystem::kSI;
  QLabel* picked_label_;
  std::vector<int> picked_;
  std::vector<std::array<double, 2>> picked_at_;
};

}  // namespace drape
