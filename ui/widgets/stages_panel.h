// The stages of a scene in order: each one's kind, initial increment Δλ₀ and
// control; reorder and remove. Every change is checked by the scene reader's
// own rules (a released gripper cannot move later, …) before it becomes an
// undoable edit; a refused one says why.
#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;

namespace drape {

class SceneDocument;
struct Scene;

class StagesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit StagesPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QDoubleSpinBox* increment() const { return increment_; }
  QComboBox* control() const { return control_; }
  QString message() const;

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
  QComboBox* control_;
  QLabel* message_;
  bool refreshing_ = false;
};

}  // namespace drape
