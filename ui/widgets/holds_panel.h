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

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;

namespace drape {

class SceneDocument;
struct Scene;

class HoldsPanel : public QWidget {
  Q_OBJECT
 public:
  enum class Role { kSupports, kGrippers };
  HoldsPanel(Role role, SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QString message() const;

  // rule: "left", "right", "bottom", "top" (an edge), "corners", "point"
  // (at x, y [m]) or "picked" (the nodes picked in the viewport); fixity
  // 0: position, 1: clamp.
  bool add(const QString& rule, int fixity, double x = 0, double y = 0);
  bool setFixity(int fixity);  // of the selected one
  // The selected one now holds the picked nodes.
  bool holdPicked();
  bool removeSelected();

 public slots:
  void refresh();
  void setPickedNodes(const std::vector<int>& nodes);

 private:
  bool Apply(const QString& what, const Scene& after);

  Role role_;
  SceneDocument* document_;
  QListWidget* list_;
  QComboBox *rule_, *fixity_;
  QDoubleSpinBox *x_, *y_;
  QLabel *message_, *picked_label_;
  std::vector<int> picked_;
  bool refreshing_ = false;
};

}  // namespace drape
