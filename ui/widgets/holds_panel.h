// What holds the part: its supports (fixed for the whole run) or its
// grippers (moved along the stages' paths, released by a stage). Each one's
// name, which nodes it holds — a selection rule of reference coordinates,
// so it holds at any mesh density, or nodes picked in the viewport — and
// how (position or clamp). Every change is checked by the scene reader's
// and the engine's own rules first (a rule that matches no node, a gripper
// a stage still moves, are refused with their messages) and is one
// undoable edit.
#pragma once

#include <QWidget>

#include <array>
#include <vector>

#include "core/model/scene.h"
#include "core/model/unit_system.h"

class QComboBox;
class QLabel;
class QListWidget;

namespace drape {

class SceneDocument;
class SelectionRuleEditor;

class HoldsPanel : public QWidget {
  Q_OBJECT
 public:
  enum class Role { kSupports, kGrippers };
  HoldsPanel(Role role, SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  SelectionRuleEditor* rule() const { return rule_; }
  QString message() const;

  // rule: "left", "right", "bottom", "top" (an edge), "corners", "point"
  // (at x, y [m]) or "picked" (the nodes picked in the viewport: one is
  // held as the point where it is, which any mesh density finds; several
  // by their numbers, which hold only on this mesh); fixity 0: position,
  // 1: clamp.
  bool add(const QString& rule, int fixity, double x = 0, double y = 0);
  bool setFixity(int fixity);  // of the selected one
  // The selected one now holds the picked nodes.
  bool holdPicked();
  bool removeSelected();

 public slots:
  void refresh();
  // Coordinates shown in `system`'s unit of length (typing takes any unit).
  void setUnitSystem(UnitSystem system);
  // The nodes picked in the viewport and their reference (x, y) [m].
  void setPickedNodes(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);

 private:
  bool Apply(const QString& what, const Scene& after);
  bool AddHold(const Selection& selection, int fixity);

  Role role_;
  SceneDocument* document_;
  QListWidget* list_;
  SelectionRuleEditor* rule_;
  QComboBox* fixity_;
  QLabel* message_;
  bool refreshing_ = false;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
