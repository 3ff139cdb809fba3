// The stages of a scene in order: each one's kind, initial increment Δλ₀,
// control, the grippers it releases and its moves (MoveEditor); add,
// reorder and remove. Every change is checked by the scene reader's
// own rules (a released gripper cannot move later, …) before it becomes an
// undoable edit; a refused one says why.
#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;

namespace drape {

class MoveEditor;
class SceneDocument;
struct Scene;

class StagesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit StagesPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QDoubleSpinBox* increment() const { return increment_; }
  QComboBox* control() const { return control_; }
  MoveEditor* moves() const { return moves_; }
  QString message() const;

  // A new last stage of kind "gravity", "load", "move" (carrying the first
  // gripper 5 cm up) or "hold", selected.
  bool addStage(const QString& kind);
  // The grippers the selected stage lets go of, comma separated.
  bool setRelease(const QString& names);

  // The selected stage one place up or down, or removed; false (with the
  // reason shown) when the scene would not be valid.
  bool moveSelected(int by);
  bool removeSelected();
  bool setIncrement(double value);
  bool setControl(int index);  // 0: arc length, 1: load

 public slots:
  void refresh();

 private:
  bool Apply(const QString& what, const Scene& after);

  SceneDocument* document_;
  QListWidget* list_;
  QDoubleSpinBox* increment_;
  QComboBox *control_, *new_kind_;
  QLineEdit* release_;
  MoveEditor* moves_;
  QLabel* message_;
  bool refreshing_ = false;
};

}  // namespace drape
