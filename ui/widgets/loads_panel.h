// The point loads of a scene: a total force [N] and moment [N·m] shared
// over the nodes a rule selects (an edge, the corners, a point, picked
// nodes), applied by the scene's "load" stages. Force and moment are typed
// with units ("0, 0, -2 gf") and read by the scene reader.
#pragma once

#include <QWidget>

#include <array>
#include <vector>

#include "core/model/unit_system.h"

class QLabel;
class QLineEdit;
class QListWidget;

namespace drape {

class SceneDocument;
class SelectionRuleEditor;
struct Scene;
struct Selection;

class LoadsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit LoadsPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  // The rule rows: the selected load's rule, or the one a new load takes.
  SelectionRuleEditor* rule() const { return rule_; }
  QString message() const;

  // A new load on `rule` (as SelectionRuleEditor: "right", "point", …)
  // with the typed force and moment.
  bool add(const QString& rule,
           const QString& force,
           const QString& moment = "0, 0, 0",
           double x = 0,
           double y = 0);
  // The selected load's force and moment.
  bool setForce(const QString& force, const QString& moment);
  bool removeSelected();

 public slots:
  void refresh();
  // The loads shown in `system`'s units (typing takes any unit).
  void setUnitSystem(UnitSystem system);
  void setPickedNodes(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);

 private:
  bool ApplyLoad(int index, const Scene& with, const QString& force, const QString& moment);
  bool AddLoad(const Selection& selection, const QString& force, const QString& moment);

  SceneDocument* document_;
  QListWidget* list_;
  SelectionRuleEditor* rule_;
  QLineEdit *force_, *moment_;
  QLabel* message_;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
